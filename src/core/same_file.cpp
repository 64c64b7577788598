#include "armmimic/core/same_file.h"

#include <filesystem>
#include <system_error>

#include <dirent.h>
#include <sys/stat.h>

namespace armmimic {
namespace {

struct FileId {
  dev_t dev = 0;
  ino_t ino = 0;
  bool operator==(const FileId& o) const { return dev == o.dev && ino == o.ino; }
};

// The file `path` leads to (symlinks followed), if it exists.
bool IdOf(const std::string& path, FileId* id, bool* is_dir = nullptr) {
  struct stat st {};
  if (path.empty() || ::stat(path.c_str(), &st) != 0) return false;
  *id = {st.st_dev, st.st_ino};
  if (is_dir) *is_dir = S_ISDIR(st.st_mode);
  return true;
}

struct InputFile {
  FileId id;
  const NamedPath* named;
  std::string path;  // the folder entry when the input is a folder
};

// The inputs as files: a folder contributes every entry directly in it (names only are read).
std::vector<InputFile> InputFiles(const std::vector<NamedPath>& inputs) {
  std::vector<InputFile> files;
  for (const NamedPath& in : inputs) {
    FileId id;
    bool is_dir = false;
    if (!IdOf(in.path, &id, &is_dir)) continue;
    if (!is_dir) {
      files.push_back({id, &in, in.path});
      continue;
    }
    DIR* dir = ::opendir(in.path.c_str());
    if (!dir) continue;
    while (const dirent* e = ::readdir(dir)) {
      const std::string name = e->d_name;
      if (name == "." || name == "..") continue;
      const std::string entry = in.path + (in.path.back() == '/' ? "" : "/") + name;
      FileId entry_id;
      bool entry_is_dir = false;
      if (IdOf(entry, &entry_id, &entry_is_dir) && !entry_is_dir) {
        files.push_back({entry_id, &in, entry});
      }
    }
    ::closedir(dir);
  }
  return files;
}

std::string Named(const NamedPath& p) { return p.role + " " + p.path; }

}  // namespace

Status CheckOutputsAreNotInputs(const std::vector<NamedPath>& inputs,
                                const std::vector<NamedPath>& outputs) {
  std::vector<InputFile> files;
  bool listed = false;
  for (const NamedPath& out : outputs) {
    FileId id;
    if (!IdOf(out.path, &id)) continue;  // a new file replaces nothing
    if (!listed) {
      files = InputFiles(inputs);
      listed = true;
    }
    for (const InputFile& in : files) {
      if (!(in.id == id)) continue;
      const std::string input =
          in.path == in.named->path ? Named(*in.named) : in.path + " (in " + Named(*in.named) + ")";
      return Status::Error(Named(out) + " is the same file as " + input +
                           " (an input): writing it would replace the input; choose another "
                           "output");
    }
  }
  return Status::Ok();
}

Status CheckOutputsAreDistinct(const std::vector<NamedPath>& outputs) {
  namespace fs = std::filesystem;
  std::vector<std::string> resolved;
  std::vector<std::pair<bool, FileId>> ids;
  for (const NamedPath& out : outputs) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(out.path, ec), ec);
    resolved.push_back(ec ? fs::path(out.path).lexically_normal().string() : p.string());
    FileId id;
    const bool exists = IdOf(out.path, &id);
    ids.emplace_back(exists, id);
  }
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      const bool same_file = ids[i].first && ids[j].first && ids[i].second == ids[j].second;
      if (resolved[i] == resolved[j] || same_file) {
        return Status::Error(Named(outputs[j]) + " and " + Named(outputs[i]) +
                             " are the same file: one would replace the other");
      }
    }
  }
  return Status::Ok();
}

}  // namespace armmimic
