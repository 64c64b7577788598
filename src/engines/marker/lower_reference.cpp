// The reference's lower markers measured for a given silhouette, and the silhouette's edges
// checked against them and against the rows beside them (docs/marker.md, "Calibration", steps 2
// and 4): equal discs for an unsure edge, each limb fitted over all its rows, and a step that is
// the joint's shadow's far edge.
#include "marker/lower_reference.h"

#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"
#include "marker/limb.h"

namespace armmimic::internal {
namespace {

// How far (pixels) fitting a limb over all its rows may move an edge the steps placed.
constexpr double kLimbReach = 2;
// A plain step's edge is confirmed by its fitted limb within this many pixels.
constexpr double kLimbAgreement = 1;
// An unsure edge is moved to its fitted limb unless the steps' edge shows the lower markers as
// equal discs by this much more (a share of the radii's sum).
constexpr double kLimbPreference = 0.003;
// The joint's shadow beside a dark limb: a band flat within kShadowFlat grey levels, at least
// kShadowMinWidth columns wide, darker by kShadowContrast than the wall beyond it and than the
// surface kShadowRamp columns inside it.
constexpr double kShadowFlat = 4, kShadowContrast = 25;
constexpr int kShadowMinWidth = 4, kShadowRamp = 6;
// How far (degrees) the lower markers' mid-angle may lie from the upper marker's (AboutTheUpper).
constexpr double kAboutTheUpperDeg = 15;

}  // namespace

// Marker grey over surface grey at the two markers' centres, then the markers measured with it:
// their zero-yaw angles, angular radius and height.
bool MeasureReferenceMarkers(const cv::Mat& gray, const MarkerCamera& camera, int x0,
                             const std::vector<double>& surface, bool allow_cut,
                             LowerCalibration* cal, LowerScan* scan, std::string* message) {
  LowerScratch scratch;
  for (int pass = 0; pass < 2; ++pass) {
    MeasureLowerMarkers(gray, *cal, x0, surface, true, scan, &scratch);
    // A marker the limb cuts is read from its inner end and the disc's half-chord, which needs
    // the markers' angular radius: the whole one's.
    if (allow_cut && scan->markers.size() == 1 && !scan->markers[0].cut && cal->delta == 0) {
      cal->delta = scan->markers[0].radius;
      MeasureLowerMarkers(gray, *cal, x0, surface, true, scan, &scratch);
    }
    if (scan->markers.size() != 2) {
      *message = "found " + std::to_string(scan->markers.size()) +
                 " dark patches across the joint at the lower markers' height, expected 2";
      return false;
    }
    if (pass == 1) break;
    double ratio = 0;
    for (const LowerMarker& m : scan->markers) {
      const cv::Point c(static_cast<int>(std::lround(m.centre_px.x)),
                        static_cast<int>(std::lround(m.centre_px.y)));
      double sum = 0;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) sum += gray.at<uchar>(c.y + dy, c.x + dx);
      }
      ratio += sum / 9 / std::max(1.0, surface[c.x - x0]);
    }
    cal->marker_ratio = std::clamp(0.5 * ratio, 0.0, 0.8);
  }
  const LowerMarker& l = scan->markers[0];
  const LowerMarker& r = scan->markers[1];
  cal->theta_left0 = l.theta;
  cal->theta_right0 = r.theta;
  cal->delta = l.cut ? r.radius : r.cut ? l.radius : 0.5 * (l.radius + r.radius);
  const double f = camera.focal_px, cy = camera.principal_px.y;
  const CylinderView& c = scan->cylinder;
  cal->height = 0.5 * ((cy - l.centre_px.y) * c.Depth(l.theta) / f +
                       (cy - r.centre_px.y) * c.Depth(r.theta) / f);
  return true;
}

// At zero yaw the lower markers lie either side of the front, where the upper marker is: their
// mid-angle is the upper marker's angle. Centroids under side light, a tilted camera and the
// upper marker's other height make that approximate (up to 10 degrees on the tuning rigs), so
// only a calibration that misses it by more than kAboutTheUpperDeg is refused: its silhouette
// or its triple is something else (a wall blob taken for a marker, a limb placed 30 px out).
bool AboutTheUpper(const MarkerCamera& camera, cv::Point2d upper_px, const LowerCalibration& cal,
                   std::string* message) {
  const CylinderView view(camera, cal.left_edge_px, cal.right_edge_px);
  if (!view.valid()) {
    *message = "the calibrated silhouette does not fit the camera's field of view";
    return false;
  }
  const double off =
      DegFromRad(0.5 * (cal.theta_left0 + cal.theta_right0) - view.ThetaFromX(upper_px.x));
  if (std::abs(off) <= kAboutTheUpperDeg) return true;
  *message = "the lower markers do not lie either side of the upper one (their middle is " +
             std::to_string(static_cast<int>(std::lround(off))) + " degrees from it)";
  return false;
}

double HiddenEdge(const MarkerCamera& camera, double known, int hidden_side, cv::Point2d left_px,
                  cv::Point2d right_px, cv::Point2d upper_px) {
  auto misfit = [&](double other) {
    const CylinderView c =
        hidden_side == 1 ? CylinderView(camera, known, other) : CylinderView(camera, other, known);
    if (!c.valid()) return kNaN;
    return c.ThetaFromX(left_px.x) + c.ThetaFromX(right_px.x) - 2 * c.ThetaFromX(upper_px.x);
  };
  const double n = right_px.x - left_px.x;
  const double sign = hidden_side == 1 ? 1 : -1;
  // The hidden edge lies beyond the far marker, at most 3 pair-spacings from the known edge.
  const double far = hidden_side == 1 ? right_px.x : left_px.x;
  double a = far + sign, b = known + sign * 3 * n;
  double fa = misfit(a), fb = misfit(b);
  if (!(fa * fb < 0)) return kNaN;
  for (int it = 0; it < 60; ++it) {
    const double m = 0.5 * (a + b), fm = misfit(m);
    if (fa * fm <= 0) {
      b = m, fb = fm;
    } else {
      a = m, fa = fm;
    }
  }
  return 0.5 * (a + b);
}

void StartAtEdges(const MarkerCamera& camera, double left, double right, LowerCalibration* cal,
                  LowerScan* scan) {
  cal->left_edge_px = left;
  cal->right_edge_px = right;
  cal->delta = 0;
  cal->marker_ratio = LowerCalibration().marker_ratio;
  *scan = LowerScan();
  scan->left_edge_px = left;
  scan->right_edge_px = right;
  scan->cylinder = CylinderView(camera, left, right);
}

// The lower markers are equal discs: measured across the cylinder they have the same angular
// radius, whatever the camera's tilt (both lie at one height). A silhouette edge placed wrongly
// stretches the angles on its side, so the weaker edge is moved (within a third of a radius)
// to where the two radii agree best, when they differ by over 3 % at the steps' edges. Markers
// the limb cuts give no radius and leave the edges as they are.
void EqualDiscs(const cv::Mat& gray, const MarkerCamera& camera, int x0,
                const std::vector<double>& surface, int weak, LowerCalibration* cal,
                LowerScan* scan) {
  auto unequal = [](const LowerScan& sc) {
    const double a = sc.markers[0].radius, b = sc.markers[1].radius;
    if (sc.markers[0].cut || sc.markers[1].cut || !(a > 0) || !(b > 0)) return kNaN;
    return std::abs(a - b) / (a + b);
  };
  double best = unequal(*scan);
  if (!(best > 0.03)) return;
  const double start = weak == 0 ? cal->left_edge_px : cal->right_edge_px;
  const double reach = 0.35 * 0.5 * (cal->right_edge_px - cal->left_edge_px);
  const LowerCalibration base = *cal;
  for (double d = -reach; d <= reach; d += 0.25) {
    LowerCalibration c = base;
    LowerScan sc;
    double edges[2] = {base.left_edge_px, base.right_edge_px};
    edges[weak] = start + d;
    StartAtEdges(camera, edges[0], edges[1], &c, &sc);
    std::string ignored;
    if (!sc.cylinder.valid() ||
        !MeasureReferenceMarkers(gray, camera, x0, surface, false, &c, &sc, &ignored)) {
      continue;
    }
    const double q = unequal(sc);
    if (q < best) best = q, *cal = c, *scan = sc;
  }
}

// Each limb fitted over every row that shows it (FitLimb), within kLimbReach pixels of where
// the steps put it. A plain step's edge stays (the fit confirms it within kLimbAgreement); an
// unsure one (a faint step, or bands that disagree) moves to its fitted limb unless the steps'
// edge shows the lower markers as clearly more equal discs, and the markers are measured again
// (a marker the limb cuts read from its inner end). True when both limbs fit and confirm: the
// silhouette is then sure enough to size a single lower marker by its reference angle.
bool RefineLimbs(const cv::Mat& gray, const MarkerCamera& camera, int x0,
                 const std::vector<double>& surface, const std::vector<int>& rows, double y_ref,
                 const bool plain[2], LowerCalibration* cal, LowerScan* scan, bool* either_fitted) {
  const LimbFit fits[2] = {FitLimb(gray, rows, cal->left_edge_px, y_ref, 1, kLimbReach),
                           FitLimb(gray, rows, cal->right_edge_px, y_ref, -1, kLimbReach)};
  *either_fitted = fits[0].ok || fits[1].ok;
  for (int side = 0; side < 2; ++side) {
    cal->limb_x[side] = fits[side].ok ? fits[side].x : kNaN;
    cal->limb_lean[side] = fits[side].ok ? fits[side].lean : kNaN;
  }
  bool sure = true;
  bool can_move[2] = {false, false};
  for (int side = 0; side < 2; ++side) {
    const double edge = side == 0 ? cal->left_edge_px : cal->right_edge_px;
    if (!fits[side].ok) {
      sure = false;
    } else if (plain[side]) {
      sure &= std::abs(fits[side].x - edge) <= kLimbAgreement;
    } else {
      can_move[side] = true;
    }
  }
  if (!can_move[0] && !can_move[1]) return sure;
  // An unsure side: the steps' edge or the fitted limb, whichever shows the two lower markers
  // as the more nearly equal discs (the fitted limb within kLimbPreference).
  const double steps[2] = {cal->left_edge_px, cal->right_edge_px};
  double best = 1e9;
  LowerCalibration c;
  LowerScan sc;
  for (int combo = 0; combo < 4; ++combo) {
    const bool use[2] = {(combo & 1) != 0, (combo & 2) != 0};
    if ((use[0] && !can_move[0]) || (use[1] && !can_move[1])) continue;
    LowerCalibration cc = *cal;
    LowerScan ss;
    StartAtEdges(camera, use[0] ? fits[0].x : steps[0], use[1] ? fits[1].x : steps[1], &cc, &ss);
    std::string ignored;
    if (!ss.cylinder.valid() ||
        !MeasureReferenceMarkers(gray, camera, x0, surface, true, &cc, &ss, &ignored)) {
      continue;
    }
    const LowerMarker& l = ss.markers[0];
    const LowerMarker& r = ss.markers[1];
    const double q = (l.cut || r.cut || !(l.radius > 0) || !(r.radius > 0)
                          ? 0.0
                          : std::abs(l.radius - r.radius) / (l.radius + r.radius)) -
                     kLimbPreference * (use[0] + use[1]);
    if (q < best) best = q, c = cc, sc = ss;
  }
  if (best > 1) return false;
  *cal = c;
  *scan = sc;
  return sure;
}

double ShadowedLimb(const std::vector<double>& profile, int x0, double step, int side,
                    double marker_x) {
  const int n = static_cast<int>(profile.size());
  const int in = side == 0 ? 1 : -1;  // towards the markers
  const int s0 = static_cast<int>(std::lround(step)) - x0;
  const int beyond = s0 - 3 * in, first = s0 + 2 * in;
  if (beyond < 0 || beyond >= n || first < 0 || first >= n) return kNaN;
  const double level = profile[first];
  int c = first;
  while (c + in >= 0 && c + in < n && std::abs(profile[c + in] - level) <= kShadowFlat) c += in;
  const int ramp = c + kShadowRamp * in;  // the surface rises within these columns
  if (std::abs(c - first) < kShadowMinWidth || ramp < 0 || ramp >= n ||
      profile[beyond] - level < kShadowContrast ||
      std::max(profile[ramp], profile[c + (kShadowRamp / 2) * in]) - level < kShadowContrast ||
      in * (marker_x - (x0 + c)) <= 0) {
    return kNaN;
  }
  return x0 + c + 0.5 * in;
}

}  // namespace armmimic::internal
