// The signed yaw from the lower markers (docs/marker.md, "Yaw"). A yaw psi turns every surface
// point about the axis, so each lower marker's angle is its reference angle plus psi: each one
// alone gives psi, two give a consistency check and a weighted mean. A single marker could be
// either one; a side is ruled out when it puts the other marker where the image shows no dark
// patch although one would show.
#include "marker/yaw.h"

#include <algorithm>
#include <cmath>

#include "armmimic/core/angle_file.h"
#include "armmimic/core/angles.h"

namespace armmimic::internal {
namespace {

double Wrap(double a) {
  while (a <= -kPi) a += 2 * kPi;
  while (a > kPi) a -= 2 * kPi;
  return a;
}

// How far a marker's predicted angle may be off (the yaw's own error, the model's on a lens or
// rig it only approximates): near a limb a marker that far further round may be hidden.
constexpr double kPredictionMarginDeg = 4;

// A pair of lower markers read through a reference too unsure to size one marker alone may
// disagree by this much more (degrees) within kNearZeroDeg of zero yaw (see SolveYaw).
constexpr double kNearZeroAgreementDeg = 2.5;
constexpr double kNearZeroDeg = 12;

enum class OtherMarker { kUndecided, kMissing };

// Would the marker at `theta` show in the band even `kPredictionMarginDeg` further round, and
// does it not? Missing when it would show at least a pixel wide and the image has well under
// half of its dark area there. The silhouette's edge pixels mix in the background and tell
// nothing.
OtherMarker OtherMarkerAt(const LowerScan& scan, const LowerCalibration& cal, double theta,
                          const LowerMarker& seen) {
  const CylinderView& cyl = scan.cylinder;
  const double round =
      theta >= 0 ? RadFromDeg(kPredictionMarginDeg) : -RadFromDeg(kPredictionMarginDeg);
  const double lo = std::max(theta + round - cal.delta, -cyl.limb());
  const double hi = std::min(theta + round + cal.delta, cyl.limb());
  if (hi <= lo) return OtherMarker::kUndecided;
  const double x0 = std::max(cyl.XFromTheta(lo), scan.left_edge_px + 1);
  const double x1 = std::min(cyl.XFromTheta(hi), scan.right_edge_px - 1);
  const double width = x1 - x0;
  if (width < 1) return OtherMarker::kUndecided;  // too thin to tell
  // A disc's mean chord is pi/4 of its diameter; the part past the limb shows its middle rows.
  const double expected = width * 0.75 * cal.marker_height_px;
  const double found = scan.CoverageBetween(x0 - 1, x1 + 1, &seen);
  return found < 0.35 * expected ? OtherMarker::kMissing : OtherMarker::kUndecided;
}

// One lower marker: it could be the left or the right one, each side giving its own yaw; a side
// is marked where the image contradicts it (the other marker would show and does not).
YawSolution OneMarker(const LowerScan& scan, const LowerCalibration& cal, const LowerMarker& seen) {
  YawSolution out;
  const double spacing0 = cal.theta_right0 - cal.theta_left0;
  for (int side = 0; side < 2; ++side) {
    YawHypothesis h;
    h.yaw = Wrap(seen.theta - (side == 0 ? cal.theta_left0 : cal.theta_right0));
    h.sigma = seen.sigma;
    (side == 0 ? h.left : h.right) = &seen;
    const double other = side == 0 ? seen.theta + spacing0 : seen.theta - spacing0;
    h.other_missing = OtherMarkerAt(scan, cal, other, seen) == OtherMarker::kMissing;
    out.hypotheses.push_back(h);
  }
  return out;
}

}  // namespace

YawSolution SolveYaw(const LowerScan& scan, const LowerCalibration& cal, double agreement_sigmas,
                     double max_turn) {
  YawSolution out;
  const std::vector<LowerMarker>& m = scan.markers;
  if (m.empty()) {
    out.note = "no lower marker faces the camera";
    return out;
  }
  // Nearly edge-on markers help, but alone they are too foreshortened to read.
  const bool any_facing = std::any_of(m.begin(), m.end(), [&](const LowerMarker& k) {
    return std::abs(scan.cylinder.Facing(k.theta)) <= max_turn;
  });
  if (!any_facing) {
    out.note = "every lower marker is turned more than " + FormatNumber(DegFromRad(max_turn), 0) +
               " degrees from the camera";
    return out;
  }
  if (m.size() >= 2) {
    // The pair whose spacing is the reference's: left and right, each giving the yaw.
    double best = 1e9;
    YawHypothesis h;
    bool agree = false;
    for (std::size_t i = 0; i < m.size(); ++i) {
      for (std::size_t j = i + 1; j < m.size(); ++j) {
        const double yl = m[i].theta - cal.theta_left0;
        const double yr = m[j].theta - cal.theta_right0;
        const double spread = std::hypot(m[i].sigma, m[j].sigma);
        const double misfit = std::abs(yl - yr);
        if (misfit >= best) continue;
        best = misfit;
        // A reference too unsure to size one marker may have its markers' zero angles degrees
        // off, and a pair then disagrees by degrees. Near zero yaw the view looks like the
        // reference, where each marker reads its own zero angle whatever the calibration, so
        // the pair's errors stay small and its mean cancels their common part: there the pair
        // may disagree by kNearZeroAgreementDeg more (tuning and validation rigs: yaws within
        // 2.4 degrees, at most a third of the yaw, where such pairs were lost).
        const bool near_zero =
            !cal.single_sized && std::abs(0.5 * (yl + yr)) <= RadFromDeg(kNearZeroDeg);
        agree = misfit <=
                agreement_sigmas * spread + RadFromDeg(near_zero ? 1 + kNearZeroAgreementDeg : 1);
        const double wl = 1 / (m[i].sigma * m[i].sigma), wr = 1 / (m[j].sigma * m[j].sigma);
        h.yaw = Wrap((wl * yl + wr * yr) / (wl + wr));
        h.sigma = 1 / std::sqrt(wl + wr);
        h.left = &m[i];
        h.right = &m[j];
      }
    }
    if (agree) {
      out.hypotheses.push_back(h);
      return out;
    }
    // A marker the limb cuts is read from one end only; when it disagrees, the whole one is read
    // alone: the other patch may not be a marker at all (shading at the limb), so the pair's
    // order does not tell which one the whole one is.
    const LowerMarker* whole = h.left->cut == h.right->cut ? nullptr
                               : h.left->cut               ? h.right
                                                           : h.left;
    if (!whole || std::abs(scan.cylinder.Facing(whole->theta)) > max_turn) {
      out.note = "the two lower markers disagree by " + FormatNumber(DegFromRad(best), 1) +
                 " degrees of yaw";
      return out;
    }
    return OneMarker(scan, cal, *whole);
  }
  return OneMarker(scan, cal, m[0]);
}

}  // namespace armmimic::internal
