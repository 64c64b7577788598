// The parameter table of the pose engine (a pose network): one row per option (option_table.h). The
// engines test checks it against its struct (same defaults, every field listed, ranges that pass
// Check()).
#include "armmimic/core/option_rows.h"
#include "armmimic/engines/option_fields.h"

namespace armmimic {
namespace {

using namespace option_rows;  // NOLINT(google-build-using-namespace): the row builders
using P = PoseOptions;

}  // namespace

const std::vector<OptionField<PoseOptions>>& PoseOptionFields() {
  static const std::vector<OptionField<P>> fields = {
      Enum<P>("network", &P::network, PoseNetworkKind::kMoveNet, {"movenet", "blazepose"},
              "Network",
              "movenet: MoveNet Lightning, 2-D keypoints; blazepose: BlazePose full, 2-D and 3-D "
              "landmarks")
          .Flag("--network")
          .Main(),
      Enum<P>("side", &P::side, PoseSide::kAuto, {"auto", "left", "right", "both"}, "Arm",
              "the person's own arm (auto: the better seen over the first second; both: each "
              "arm into its own angle file, from the same inferences)")
          .Flag("--side")
          .Main(),
      Real<P>("min_score", &P::min_score, 0.4, 0, 1, 2, "Minimum keypoint score",
              "a shoulder, elbow or wrist scored lower is not seen: lost")
          .Main(),
      Real<P>("min_length_ratio", &P::min_length_ratio, 0.55, 0, 1, 2, "Minimum segment length",
              "a segment shorter than this share of its usual length points at the camera: lost")
          .Main(),
      Real<P>("crop_score", &P::crop_score, 0.2, 0, 1, 2, "Crop keypoint score",
              "keypoints above this score place the next frame's crop"),
      Real<P>("arm_crop", &P::arm_crop, 1.5, 0, 4, 2, "Arm look size",
              "a second look through a square this many times the upper body's extent gives the "
              "directions (0: one look)"),
      Real<P>("max_disagreement_deg", &P::max_disagreement_deg, 15, 1, 180, 1,
              "Maximum disagreement",
              "a segment whose direction differs more between the looks "
              "(degrees) is lost"),
      Real<P>("max_network_disagreement_deg", &P::max_network_disagreement_deg, 25, 1, 180, 1,
              "Maximum network disagreement",
              "blazepose: a segment farther from MoveNet's, the second opinion, than a turn of "
              "this many degrees is lost"),
      Bool<P>("flip", &P::flip, false, "Mirrored look",
              "also look at the mirrored crop and average (one more inference per frame)"),
  };
  return fields;
}

}  // namespace armmimic
