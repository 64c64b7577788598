// FitAnywhere (arm_model_fit.h): the search over every pose the arm can take, made every frame
// so that a far-apart pose explaining the image as well is always noticed.
#include "common/arm_model_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "armmimic/core/angles.h"
#include "common/arm_strip.h"
#include "common/evidence_bound.h"

namespace armmimic::arm {
namespace {

using pairs::Add;
using pairs::Pair;
using pairs::PairOf;
using pairs::PairSampler;
using pairs::Scale;
using strips::ForeTo;
using strips::kCoarseAcross;
using strips::kForeFrom;
using strips::kReachMargin;
using strips::kUpperFrom;
using strips::kUpperTo;
using strips::ScoreStrip;
using strips::ScoreStripUnless;
using strips::Steps;
using strips::StepsOf;
using strips::WholeDegreeDirection;

// The wide search's grid (degrees) and the distance between its poses that counts as another
// pose.
constexpr double kWideUpperStep = 4, kWideBendStep = 5;
constexpr double kDistinctDeg = 12;
constexpr double kRefineDeg = 4;
// How far below the last frame's floor the wide search gives a pose up: a frame's peaks move
// little from the last frame's; where they sink more, the search scores in full.
constexpr double kFloorSlack = 0.1;

// The grid: rows of the upper arm's direction, columns of the bend.
constexpr int kRows = static_cast<int>(360 / kWideUpperStep);
constexpr int kColumns = 2 * static_cast<int>(kMaxBendDeg / kWideBendStep) + 1;
// The grid's directions are whole degrees (whole steps from whole degrees).
static_assert(kWideUpperStep == 4 && kWideBendStep == 5 && kMaxBendDeg == 150);
int UpperDegOf(int row) { return -180 + 4 * (row + 1); }
int BendDegOf(int column) { return -150 + 5 * column; }

// A cell given up holds kGaveUp, below any total (-2..2) and below any floor: it is then below
// every cell that reaches the floor, as its own total would be.
constexpr double kGaveUp = -3;

// The coarse totals of every pose of the grid, row by row; with a floor, the poses that can no
// longer reach it given up.
class WideGrid {
 public:
  WideGrid(const EvidenceMap& evidence, const ArmShape& shape, const cv::Point2d& shoulder,
           double floor)
      : map_(evidence),
        shape_(shape),
        shoulder_(shoulder),
        floor_(floor),
        fore_steps_(StepsOf(shape.fore_px, kForeFrom, ForeTo(shape), true)),
        upper_(kRows),
        elbows_(kRows),
        total_(static_cast<std::size_t>(kRows * kColumns)) {
    if (floor_ > kGaveUp && kCoarseAcross * shape.fore_hw <= EvidenceBound::kReach) {
      bound_.emplace(evidence);
    }
  }

  // Scores every cell; true when some were given up.
  bool Fill() {
    const Steps upper_steps = StepsOf(shape_.upper_px, kUpperFrom, kUpperTo, true);
    bool gave_up = false;
    for (int i = 0; i < kRows; ++i) {
      const cv::Point2d& u = WholeDegreeDirection(UpperDegOf(i));
      upper_[i] = ScoreStrip(map_, upper_steps, shoulder_, u, shape_.upper_hw).score;
      elbows_[i] = shoulder_ + shape_.upper_px * u;
      for (int j = 0; j < kColumns; ++j) {
        double& t = total_[static_cast<std::size_t>(i * kColumns + j)];
        t = Unreachable(i, j) ? kGaveUp : Fore(i, j, floor_ > kGaveUp);
        gave_up = gave_up || t == kGaveUp;
      }
    }
    return gave_up;
  }

  // Scores the given-up cells in full.
  void Rescore() {
    for (int k = 0; k < kRows * kColumns; ++k) {
      double& t = total_[static_cast<std::size_t>(k)];
      if (t == kGaveUp) t = Fore(k / kColumns, k % kColumns, false);
    }
  }

  const std::vector<double>& total() const { return total_; }

 private:
  // The forearm's strip at its most (every inside sample at its bound, the flanks at 0) cannot
  // reach the floor: most poses, their strip on empty wall, are given up before any sample.
  bool Unreachable(int i, int j) const {
    if (!bound_) return false;
    const Pair elbow = PairOf(elbows_[i]);
    const Pair along = PairOf(WholeDegreeDirection(UpperDegOf(i) + BendDegOf(j)));
    double most = 0;
    for (int k = 0; k < fore_steps_.along; ++k) {
      most += bound_->Near(Add(elbow, Scale(fore_steps_.t[k], along)));
    }
    return most / fore_steps_.along < floor_ - upper_[i] - kReachMargin;
  }

  // The cell's total, or kGaveUp once it can no longer reach the floor (with `give_up`).
  double Fore(int i, int j, bool give_up) const {
    const cv::Point2d& elbow = elbows_[i];
    const cv::Point2d& u = WholeDegreeDirection(UpperDegOf(i) + BendDegOf(j));
    SegmentScore sf;
    if (give_up) {
      if (!ScoreStripUnless<true>(map_, fore_steps_, elbow, u, shape_.fore_hw, shoulder_, elbow,
                                  shape_.upper_hw + 1, floor_ - upper_[i], &sf)) {
        return kGaveUp;
      }
    } else {
      ScoreStripUnless<false>(map_, fore_steps_, elbow, u, shape_.fore_hw, shoulder_, elbow,
                              shape_.upper_hw + 1, 0, &sf);
    }
    return upper_[i] + sf.score;
  }

  const PairSampler map_;
  const ArmShape& shape_;
  const cv::Point2d shoulder_;
  const double floor_;
  const Steps fore_steps_;
  std::optional<EvidenceBound> bound_;
  std::vector<double> upper_;        // each row's upper arm
  std::vector<cv::Point2d> elbows_;  // each row's elbow
  std::vector<double> total_;
};

// Local maxima of the grid (the upper arm's direction wraps around), best first, as (total,
// cell); given-up cells are none.
std::vector<std::pair<double, int>> Peaks(const std::vector<double>& total) {
  std::vector<std::pair<double, int>> peaks;
  const int ri = static_cast<int>(std::ceil(kDistinctDeg / kWideUpperStep));
  const int rj = static_cast<int>(std::ceil(kDistinctDeg / kWideBendStep));
  for (int i = 0; i < kRows; ++i) {
    for (int j = 0; j < kColumns; ++j) {
      const double v = total[static_cast<std::size_t>(i * kColumns + j)];
      if (v == kGaveUp) continue;
      bool peak = true;
      for (int di = -ri; di <= ri && peak; ++di) {
        for (int dj = -rj; dj <= rj && peak; ++dj) {
          const int jj = j + dj;
          if ((di == 0 && dj == 0) || jj < 0 || jj >= kColumns) continue;
          const int ii = (i + di + kRows) % kRows;
          const double w = total[static_cast<std::size_t>(ii * kColumns + jj)];
          // Ties go to the earlier cell, so a plateau gives one peak.
          peak = w < v || (w == v && ii * kColumns + jj > i * kColumns + j);
        }
      }
      if (peak) peaks.emplace_back(v, i * kColumns + j);
    }
  }
  std::sort(peaks.begin(), peaks.end(), [](const auto& a, const auto& b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  return peaks;
}

}  // namespace

std::vector<FitResult> FitAnywhere(const EvidenceMap& evidence, const ArmShape& shape,
                                   const cv::Point2d& shoulder, int count,
                                   WideSearchMemory* memory) {
  const double floor = memory != nullptr ? memory->last_floor - kFloorSlack
                                         : -std::numeric_limits<double>::infinity();
  WideGrid grid(evidence, shape, shoulder, floor);
  const bool gave_up = grid.Fill();
  std::vector<std::pair<double, int>> peaks = Peaks(grid.total());
  if (gave_up) {
    // A cell at or above the floor is a peak exactly when it would be with every cell scored (a
    // given-up neighbour is below it either way); one below it may not be. The `count` best are
    // the same when that many reach the floor; else every given-up cell is scored in full.
    const auto reach = static_cast<int>(
        std::count_if(peaks.begin(), peaks.end(), [&](const auto& p) { return p.first >= floor; }));
    if (reach >= count) {
      peaks.resize(static_cast<std::size_t>(reach));
    } else {
      grid.Rescore();
      peaks = Peaks(grid.total());
    }
  }
  if (memory != nullptr) {
    memory->last_floor = static_cast<int>(peaks.size()) >= count && count > 0
                             ? peaks[static_cast<std::size_t>(count - 1)].first
                             : -std::numeric_limits<double>::infinity();
  }
  std::vector<FitResult> out;
  LocalSearch refine;
  refine.upper_range_deg = refine.bend_range_deg = kRefineDeg;
  for (const auto& [v, k] : peaks) {
    if (static_cast<int>(out.size()) >= count) break;
    ArmPose p;
    p.shoulder = shoulder;
    p.upper_deg = Wrap180(UpperDegOf(k / kColumns));
    p.fore_deg = Wrap180(p.upper_deg - kMaxBendDeg + kWideBendStep * (k % kColumns));
    out.push_back(FitNear(evidence, shape, p, refine));
  }
  std::sort(out.begin(), out.end(),
            [](const FitResult& a, const FitResult& b) { return a.score.total > b.score.total; });
  return out;
}

}  // namespace armmimic::arm
