// The marker joint's cylinder model (docs/marker.md): calibration from the reference, and one
// view: silhouette and lower markers -> signed yaw; upper marker -> bend.
// Length: MeasureMarkerView is one view's chain (scan, lower markers, the side of a single
// marker, upper marker), whose steps share the scan and the candidate yaws.
#include "marker/model.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "armmimic/core/angle_file.h"
#include "marker/yaw.h"

namespace armmimic::internal {

namespace {

// The darkest column of the lower part's shading in the reference: the mean grey of the rows
// between the markers, two pixels in from each limb (whose pixels mix in the background); 0 when
// there are none.
double DarkestShading(const cv::Mat& gray, const LowerCalibration& cal) {
  const int x0 = std::max(0, static_cast<int>(std::ceil(cal.left_edge_px)) + 2);
  const int x1 = std::min(gray.cols - 1, static_cast<int>(std::floor(cal.right_edge_px)) - 2);
  if (cal.bands[0].rows.empty() || x1 < x0) return 0;
  std::vector<double> profile;
  ColumnProfile(gray, cal.bands[0].rows, x0, x1 - x0 + 1, &profile);
  return *std::min_element(profile.begin(), profile.end());
}

}  // namespace

bool CalibrateMarkerJoint(const cv::Mat& gray, const MarkerCamera& camera, const MarkerTriple& t,
                          MarkerCalibration* cal, std::string* message) {
  *cal = MarkerCalibration();
  cal->camera = camera;
  LowerScan scan;
  if (!CalibrateLowerPart(gray, cal->camera, t.left.centre, t.right.centre, t.upper.centre,
                          t.upper.box.height, &cal->lower, &scan, message)) {
    return false;
  }
  const CylinderView& cyl = scan.cylinder;
  cal->radius_px = cyl.half_width_px();
  UpperCalibration& u = cal->upper;
  u.k = DiscCentroidFactor(cal->lower.delta);
  // The reference is straight: the upper marker's centroid, k times nearer the axis than its
  // centre, gives its angle; its row and the lower markers' give the pivot's height and e.
  const double x = cyl.axis_x() + (t.upper.centre.x - cyl.axis_x()) / u.k;
  u.theta0 = cyl.ThetaFromX(x);
  const double f = cal->camera.focal_px;
  const double upper_height =
      (cal->camera.principal_px.y - t.upper.centre.y) * cyl.Depth(u.theta0) / f;
  u.pivot_height = 0.5 * (upper_height + cal->lower.height);
  u.e = 0.5 * (upper_height - cal->lower.height);
  // The two parts meet at the pivot and, bent by beta, overlap within tan(beta / 2) of it along
  // their axes: a radius at a right-angle bend. Markers nearer the pivot than that would be
  // folded into the other part, so a triple that puts them there is not the joint's.
  if (!(u.e > 1)) {
    *message =
        u.e > 0 ? "the markers lie less than a radius from the pivot (e = " + FormatNumber(u.e, 2) +
                      " radii): not the joint's markers"
                : "the upper marker is not above the lower ones";
    return false;
  }
  u.marker_ratio = cal->lower.marker_ratio;
  u.marker_height_px = t.upper.box.height;
  u.face_area_px = t.upper.coverage_px;
  u.stretch_level = SampleStretch(gray, ProjectPivot(cyl, u), t.upper.centre).level;
  const double darkest = DarkestShading(gray, cal->lower);
  if (darkest > 0 && u.stretch_level > 0) u.darkest_level = darkest / u.stretch_level;
  u.support = UpperSilhouetteSupport(gray, cyl, u, 0, 0);
  u.darkness = UpperMarkerDarkness(gray, t.upper.centre, u.marker_height_px);
  return true;
}

namespace {

// A side whose upper part shows this many times the other side's silhouette support wins.
constexpr double kSupportMargin = 1.5;

// An upper marker turned at most this far from the camera shows plainly when it is there.
constexpr double kSquareDeg = 45;

// Past this the upper marker cannot be seen (a marker is unreadable past 75 degrees).
constexpr double kHiddenDeg = 80;

// How far the upper marker is turned from the camera at `yaw` (radians, >= 0).
double UpperTurn(const MarkerCalibration& cal, double yaw) {
  return std::abs(std::remainder(cal.upper.theta0 + yaw, 2 * kPi));
}

// Measures the upper marker for one yaw, when it faces the camera within `max_turn_deg`.
UpperMeasurement Upper(const cv::Mat& gray, const CylinderView& cyl, const MarkerCalibration& cal,
                       const MarkerOptions& options, double yaw, double max_turn_deg) {
  if (UpperTurn(cal, yaw) > RadFromDeg(max_turn_deg)) {
    UpperMeasurement m;
    m.note = "the upper marker is turned away";
    return m;
  }
  return MeasureUpperMarker(gray, cyl, cal.upper, yaw, options.upper_tolerance);
}

// Do both sides of one lower marker turn the joint as far? Their sizes must agree as closely as
// two markers' yaws must to be read as a pair (SolveYaw): within agreement_sigmas of their
// spreads, and a degree.
bool SameSize(const YawHypothesis& a, const YawHypothesis& b, const MarkerOptions& options) {
  const double gap = std::abs(std::abs(a.yaw) - std::abs(b.yaw));
  return gap <= options.agreement_sigmas * std::hypot(a.sigma, b.sigma) + RadFromDeg(1);
}

// Both sides of one lower marker, weighed with the upper marker looked for while it faces the
// camera within `look_deg`: a side is out when the other lower marker would show and does not,
// or when it turns the upper marker away although the other side finds it plainly. Of two sides
// left, the one whose upper marker is found plainly (its silhouette as clear as in the
// reference) wins if the other finds none.
struct SideEvidence {
  std::array<UpperMeasurement, 2> upper;
  std::array<bool, 2> alive{true, true}, plain{false, false}, telling{false, false};
};

// `nearer`: the same sides weighed with the bend's limit (max_upper_turn_deg), whose measurement
// of a side within that limit is this one's too.
SideEvidence WeighSides(const cv::Mat& gray, const CylinderView& cyl, const MarkerCalibration& cal,
                        const MarkerOptions& options, const YawSolution& yaw, double look_deg,
                        const SideEvidence* nearer = nullptr) {
  SideEvidence ev;
  for (int i = 0; i < 2; ++i) {
    const bool measured =
        nearer && UpperTurn(cal, yaw.hypotheses[i].yaw) <= RadFromDeg(options.max_upper_turn_deg);
    ev.upper[i] = measured ? nearer->upper[i]
                           : Upper(gray, cyl, cal, options, yaw.hypotheses[i].yaw, look_deg);
    ev.plain[i] = ev.upper[i].found && !ev.upper[i].ambiguous;
    // Found with its silhouette as plain as the reference's: the upper part is there.
    ev.telling[i] = ev.plain[i] && ev.upper[i].support >= 0.5 * cal.upper.support;
  }
  std::array<bool, 2>& alive = ev.alive;
  const std::array<bool, 2>& plain = ev.plain;
  const std::array<bool, 2>& telling = ev.telling;
  for (int i = 0; i < 2; ++i) {
    const bool hidden = UpperTurn(cal, yaw.hypotheses[i].yaw) > RadFromDeg(kHiddenDeg);
    alive[i] = !yaw.hypotheses[i].other_missing && !(hidden && telling[1 - i]);
    // This side turns the upper marker squarely to the camera, the other turns it away, and
    // there is no dark spot at all where this side puts it: the marker would show, and does
    // not. (A spot weighed and turned down is not enough: a marker missed that way had made a
    // side 50 degrees wrong.)
    const bool square = UpperTurn(cal, yaw.hypotheses[i].yaw) <= RadFromDeg(kSquareDeg);
    const bool away =
        UpperTurn(cal, yaw.hypotheses[1 - i].yaw) > RadFromDeg(options.max_upper_turn_deg);
    if (square && away && ev.upper[i].spots.empty()) alive[i] = false;
  }
  if (alive[0] && alive[1]) {  // the side whose upper marker shows plainly, if only one does
    if (telling[0] && !plain[1]) {
      alive[1] = false;
    } else if (telling[1] && !plain[0]) {
      alive[0] = false;
    } else if (telling[0] != telling[1]) {
      // Both find a spot, but only one side finds the upper part's silhouette round it: the
      // other side's bend puts the upper part where the image shows at most half the
      // reference's edges. The upper marker lies a radius to one side of its part's axis, the
      // side the yaw turns it to, so the wrong side's part is displaced by about two radii.
      const int t = telling[0] ? 0 : 1;
      if (ev.upper[t].support >= kSupportMargin * ev.upper[1 - t].support) alive[1 - t] = false;
    }
  }
  if (alive[0] && alive[1] && plain[0] && plain[1]) {
    // Both sides find the upper marker plainly (at two spots, or at one with two bends): the
    // test that picks among one side's spots picks among the sides, clearly or not at all, and
    // only a side whose upper part shows as plainly as in the reference wins.
    const double q0 = ev.upper[0].quality, q1 = ev.upper[1].quality;
    if (telling[0] && q0 >= q1 + kClearQuality) {
      alive[1] = false;
    } else if (telling[1] && q1 >= q0 + kClearQuality) {
      alive[0] = false;
    }
  }
  return ev;
}

}  // namespace

MarkerViewResult MeasureMarkerView(const cv::Mat& gray, const MarkerCalibration& cal,
                                   const MarkerOptions& options, MarkerViewScratch* s) {
  MarkerViewResult out;
  LowerScan& scan = s->scan;
  if (!ScanLowerPart(gray, cal.lower, cal.camera, &scan, &s->lower)) {
    out.note = scan.failure;
    return out;
  }
  const CylinderView& cyl = scan.cylinder;
  out.left_edge_px = scan.left_edge_px;
  out.right_edge_px = scan.right_edge_px;
  out.axis_x_px = cyl.axis_x();
  const std::vector<int>& below = cal.lower.bands[1].rows;
  out.bottom_row = below.empty() ? cal.lower.band_bottom : below.back();
  out.pivot_px = ProjectPivot(cyl, cal.upper);
  const int rows = static_cast<int>(std::lround(cal.lower.marker_height_px));
  for (const LowerMarker& m : scan.markers) {
    out.candidates.emplace_back(m.first_col,
                                static_cast<int>(std::lround(m.centre_px.y)) - rows / 2,
                                m.last_col - m.first_col + 1, rows);
  }
  const YawSolution yaw =
      SolveYaw(scan, cal.lower, options.agreement_sigmas, RadFromDeg(options.max_marker_turn_deg));
  if (yaw.hypotheses.empty()) {
    out.note = yaw.note;
    return out;
  }
  // One marker that could be either side (WeighSides): the upper marker looked for while it is
  // turned little enough to measure the bend and, where that leaves both sides and their sizes
  // differ, as far round as a lower marker is read: a marker seen that far round is weaker
  // evidence (foreshortened, near the limb), so it only decides what the nearer look left open.
  std::size_t pick = 0;
  bool side_seen = true;  // the single marker's side rests on the image, not the upper marker
  UpperMeasurement upper;
  if (yaw.hypotheses.size() == 1) {
    upper = Upper(gray, cyl, cal, options, yaw.hypotheses[0].yaw, options.max_upper_turn_deg);
    out.candidates.insert(out.candidates.end(), upper.spots.begin(), upper.spots.end());
  } else {
    SideEvidence sides = WeighSides(gray, cyl, cal, options, yaw, options.max_upper_turn_deg);
    const bool same_size =
        SameSize(yaw.hypotheses[0], yaw.hypotheses[1], options) && cal.lower.single_sized;
    if (sides.alive[0] && sides.alive[1] && !same_size &&
        options.max_marker_turn_deg > options.max_upper_turn_deg) {
      SideEvidence wide =
          WeighSides(gray, cyl, cal, options, yaw, options.max_marker_turn_deg, &sides);
      if (wide.alive[0] != wide.alive[1]) sides = std::move(wide);
    }
    for (const UpperMeasurement& u : sides.upper) {
      out.candidates.insert(out.candidates.end(), u.spots.begin(), u.spots.end());
    }
    const std::array<bool, 2>& alive = sides.alive;
    if (alive[0] && alive[1] && same_size) {
      // Either side, and both turn the joint as far (the marker near the front, between where
      // the two sides put it): the size of the yaw is known, its sign is not.
      out.ok = true;
      out.yaw = 0.5 * (std::abs(yaw.hypotheses[0].yaw) + std::abs(yaw.hypotheses[1].yaw));
      out.sign_known = false;
      out.note =
          "yaw from one lower marker, which could be either: both turn the joint as far; sign "
          "unknown; no bend: the upper marker's place depends on the sign";
      return out;
    }
    if (alive[0] == alive[1]) {
      out.note = alive[0] ? "one lower marker shows, and it could be either"
                          : "one lower marker shows, and the rest of the joint contradicts it";
      return out;
    }
    if (alive[1]) pick = 1;
    upper = sides.upper[pick];
    // The other side is ruled out by the lower part itself (its other lower marker would show
    // and does not), or both sides turn the joint the same
    // way, or the upper part decides plainly: this side finds the upper marker with the upper
    // part's silhouette around it, and the other side finds no dark spot at all where it puts
    // the upper marker, or turns it round the back. Otherwise the sign rests on which of two
    // dark spots looked more like the marker, which clutter or a dark wall can fake.
    const YawHypothesis& a = yaw.hypotheses[0];
    const YawHypothesis& b = yaw.hypotheses[1];
    const int other_side = 1 - static_cast<int>(pick);
    const bool upper_decides =
        sides.telling[pick] &&
        (sides.upper[other_side].spots.empty() ||
         UpperTurn(cal, yaw.hypotheses[other_side].yaw) > RadFromDeg(kHiddenDeg));
    side_seen =
        yaw.hypotheses[other_side].other_missing || (a.yaw > 0) == (b.yaw > 0) || upper_decides;
  }
  const YawHypothesis& h = yaw.hypotheses[pick];
  if (!(h.left && h.right) && !cal.lower.single_sized) {
    out.note =
        "one lower marker shows, and the reference's silhouette is too unsure to size it alone";
    return out;
  }
  out.ok = true;
  out.yaw = h.yaw;
  // Two lower markers measure the signed yaw through zero (near zero its sign is as good as its
  // value); one marker's sign is only as good as the choice of its side.
  out.sign_known = side_seen;
  if (h.left) out.left_px = h.left->centre_px;
  if (h.right) out.right_px = h.right->centre_px;
  const std::string markers = h.left && h.right ? "both lower markers"
                              : h.left          ? "the left lower marker"
                                                : "the right lower marker";
  const std::string sign = out.sign_known ? ""
                                          : "; sign unknown: the lower marker could be either, and "
                                            "the upper one does not tell plainly";
  if (upper.found && UpperTurn(cal, h.yaw) > RadFromDeg(options.max_upper_turn_deg)) {
    // Found to tell the side, but the bend plane is seen too nearly edge-on to measure the bend.
    upper.found = false;
    upper.note = "the upper marker is turned too far to measure the bend";
  }
  if (upper.found && !upper.ambiguous) {
    out.bend = upper.bend;
    out.upper_px = upper.centre_px;
    out.note = "yaw from " + markers + " (+-" + FormatNumber(DegFromRad(h.sigma), 2) +
               " deg); bend from the upper marker" + sign;
  } else {
    out.note = "yaw from " + markers + sign + "; no bend: " + upper.note;
  }
  return out;
}

}  // namespace armmimic::internal
