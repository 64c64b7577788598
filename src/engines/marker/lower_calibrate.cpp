// The lower part on the reference image (docs/marker.md, "Calibration"): the silhouette found
// from scratch around the lower pair, the bands of rows that show only the surface, the markers'
// grey ratio, angular radius, zero-yaw angles and height.
// Length: CalibrateLowerPart is the calibration's steps in order, each a few lines over shared
// measurements of the reference.
#include <algorithm>
#include <cmath>
#include <utility>

#include "armmimic/core/angles.h"
#include "marker/lower.h"
#include "marker/lower_reference.h"

namespace armmimic::internal {
namespace {

// A silhouette step fainter than this (grey levels a pixel) wanders with the noise.
constexpr double kTrackable = 5;
// ... and one fainter than this is placed better by the markers' symmetry.
constexpr double kPlain = 15;
// The lower markers' angular radii count as equal within this share of their sum (twice the
// 3 % EqualDiscs starts at).
constexpr double kEqualDiscs = 0.06;

std::vector<int> RowRange(double from, double to, int rows) {
  std::vector<int> out;
  for (int y = std::max(1, static_cast<int>(std::ceil(from)));
       y <= std::min(rows - 2, static_cast<int>(std::floor(to))); ++y) {
    out.push_back(y);
  }
  return out;
}

// The silhouette's two steps in `profiles` (each over the same columns, first column x0) either
// side of `mid` (the lower markers' midpoint), each at least `lo` and at most `hi` from it (the
// markers lie on the surface: each edge lies beyond the nearer marker's centre). Going outwards
// from the markers, each edge is the first step at least a quarter as steep as the steepest on
// its side: the limb is the first silhouette met, a shadow's or a poster's edge on the wall
// beyond it may be steeper (each band sees its own background, so a step's sign may differ).
// A step no band could track (under kTrackable) is taken only when no trackable one lies further
// out: it is the shading ramp's end where the limb's self-shadowed band begins (an edge had been
// placed 6 px inside, the markers' angles 3.6 degrees wide).
// The markers' midpoint lies off the axis when the camera sees the joint from aside, so the
// edges need not be symmetric about it.
bool SilhouetteEdges(const std::vector<std::vector<double>>& profiles, int x0, double mid,
                     double lo, double hi, int* left, int* right) {
  constexpr double kShare = 0.25, kRamp = 0.5;
  const int width = profiles.empty() ? 0 : static_cast<int>(profiles[0].size());
  std::vector<double> g(width, 0.0);
  for (int i = 1; i + 1 < width; ++i) {
    for (const std::vector<double>& p : profiles) g[i] += std::abs(p[i + 1] - p[i - 1]);
  }
  // Whether one band's slope at column i reaches kTrackable (MeasureBand's step strength).
  auto trackable = [&](int i) {
    double slope = 0;
    for (const std::vector<double>& p : profiles) {
      slope = std::max(slope, 0.5 * std::abs(p[i + 1] - p[i - 1]));
    }
    return slope >= kTrackable;
  };
  int* out[2] = {left, right};
  for (int side = 0; side < 2; ++side) {
    const int step = side == 0 ? -1 : 1;
    const int from = static_cast<int>(side == 0 ? std::floor(mid - lo) : std::ceil(mid + lo));
    const int to = static_cast<int>(side == 0 ? std::ceil(mid - hi) : std::floor(mid + hi));
    auto inside = [&](int x) { return x - x0 >= 1 && x - x0 + 1 < width; };
    double steepest = 0;
    for (int x = from; step * (to - x) >= 0; x += step) {
      if (inside(x)) steepest = std::max(steepest, g[x - x0]);
    }
    *out[side] = -1;
    if (steepest == 0) return false;
    int faint = -1;
    for (int x = from; step * (to - x) >= 0; x += step) {
      if (inside(x) && g[x - x0] >= kShare * steepest) {
        // The step's own peak, a column or two further out.
        int peak = x;
        while (inside(peak + step) && g[peak + step - x0] > g[peak - x0]) peak += step;
        // A silhouette is a step with the background flat beyond it; a gradient as steep three
        // pixels either side is the middle of the surface's shading ramp (side light).
        if (inside(peak - 3 * step) && inside(peak + 3 * step) &&
            std::min(g[peak - 3 * step - x0], g[peak + 3 * step - x0]) >= kRamp * g[peak - x0]) {
          x = peak;
          continue;
        }
        if (!trackable(peak - x0)) {
          if (faint < 0) faint = peak;
          x = peak;
          continue;
        }
        *out[side] = peak;
        break;
      }
    }
    if (*out[side] < 0) *out[side] = faint;
  }
  return *left >= 0 && *right >= 0;
}

// Measures a band's two edges near `left`, `right` (image columns): the steepest step (tracked in
// the views; one weaker than kTrackable grey levels a pixel is untrackable: strength 0)
// and the edge fitted to the profile's shape (the silhouette itself).
void MeasureBand(const cv::Mat& gray, int x0, int width, double left, double right, EdgeBand* band,
                 std::vector<double>* profile) {
  ColumnProfile(gray, band->rows, x0, width, profile);
  const double at[2] = {left, right};
  for (int side = 0; side < 2; ++side) {
    band->edge_px[side] = band->peak_px[side] = at[side];
    band->strength[side] = 0;
    if (band->rows.empty()) continue;
    const int c = static_cast<int>(std::lround(at[side])) - x0;
    ProfileEdge e = FindProfileEdge(*profile, x0, c - 2, c + 2, 0);
    // Lens distortion bends a silhouette near the image's edge: the rows between the markers and
    // those below them had put it 3 px apart, and the band below found no trackable step within
    // 2 px of the first silhouette (the reference was refused). A trackable step a little
    // further is this band's own edge.
    if (!e.found || std::abs(e.strength) < kTrackable) {
      const ProfileEdge wide = FindProfileEdge(*profile, x0, c - 4, c + 4, 0);
      if (wide.found && std::abs(wide.strength) >= kTrackable) e = wide;
    }
    if (!e.found) continue;
    band->peak_px[side] = e.x;
    band->edge_px[side] = FitProfileEdge(*profile, x0, e.x, 2.0, side == 0 ? 1 : -1);
    if (std::abs(e.strength) >= kTrackable) band->strength[side] = e.strength;
  }
}

// Mean of the bands' fitted edges on `side`, weighted by rows and squared step (a faint step
// places the edge poorly), over the bands that track it (all bands when none does); nan
// without rows.
double MeanEdge(const EdgeBand* bands, int side) {
  double sum = 0, n = 0;
  for (int pass = 0; pass < 2 && n == 0; ++pass) {
    for (int b = 0; b < 2; ++b) {
      if (pass == 0 && bands[b].strength[side] == 0) continue;
      const double w = bands[b].rows.size() *
                       (pass == 0 ? bands[b].strength[side] * bands[b].strength[side] : 1);
      sum += w * bands[b].edge_px[side];
      n += w;
    }
  }
  return n > 0 ? sum / n : kNaN;
}

// Rows of the band below the markers down to where the lower part ends: its bottom rim is seen
// from above, so the end shows first at the limbs. A row ends the band when its grey level near
// either limb or at the centre steps away from the band's median there.
std::vector<int> RowsOnTheSurface(const cv::Mat& gray, const std::vector<int>& rows, double xl,
                                  double xr) {
  if (rows.empty()) return rows;
  const int l = static_cast<int>(std::ceil(xl + 0.5)), r = static_cast<int>(std::floor(xr - 0.5));
  const int c0 = static_cast<int>(std::ceil(xl + 0.33 * (xr - xl)));
  const int c1 = static_cast<int>(std::floor(xr - 0.33 * (xr - xl)));
  const int groups[3][2] = {{l, l + 2}, {c0, c1}, {r - 2, r}};
  std::vector<double> level[3];
  for (int y : rows) {
    for (int g = 0; g < 3; ++g) {
      double sum = 0;
      for (int x = groups[g][0]; x <= groups[g][1]; ++x) sum += gray.at<uchar>(y, x);
      level[g].push_back(sum / std::max(1, groups[g][1] - groups[g][0] + 1));
    }
  }
  double median[3];
  for (int g = 0; g < 3; ++g) {
    std::vector<double> sorted = level[g];
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    median[g] = sorted[sorted.size() / 2];
  }
  std::vector<int> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    bool off = false;
    for (int g = 0; g < 3; ++g) off |= std::abs(level[g][i] - median[g]) > 0.1 * median[g] + 5;
    if (off) break;
    out.push_back(rows[i]);
  }
  return out;
}

// The same rows cut where the lower part ends, found without the band's median: near either
// limb and at the centre, the rows are split where two constant levels fit them best, and a
// split whose levels differ clearly is the part's end (the first of the three). Used when the
// median's rule keeps too few rows: the median of all rows is the wall's when the part ends
// within the band's first half, and then no row is kept.
std::vector<int> RowsBeforeTheEnd(const cv::Mat& gray, const std::vector<int>& rows, double xl,
                                  double xr) {
  if (rows.size() < 2) return rows;
  const int l = static_cast<int>(std::ceil(xl + 0.5)), r = static_cast<int>(std::floor(xr - 0.5));
  const int c0 = static_cast<int>(std::ceil(xl + 0.33 * (xr - xl)));
  const int c1 = static_cast<int>(std::floor(xr - 0.33 * (xr - xl)));
  const int groups[3][2] = {{l, l + 2}, {c0, c1}, {r - 2, r}};
  const std::size_t n = rows.size();
  std::size_t end = n;
  for (const auto& grp : groups) {
    // Prefix sums of the group's level give each split's two means and misfit.
    std::vector<double> s1(n + 1, 0.0), s2(n + 1, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      double sum = 0;
      for (int x = grp[0]; x <= grp[1]; ++x) sum += gray.at<uchar>(rows[i], x);
      const double v = sum / std::max(1, grp[1] - grp[0] + 1);
      s1[i + 1] = s1[i] + v;
      s2[i + 1] = s2[i] + v * v;
    }
    double best = 1e300;
    std::size_t split = n;
    for (std::size_t k = 1; k < n; ++k) {
      const double a = s1[k], b = s1[n] - s1[k];
      const double sse = s2[n] - a * a / k - b * b / (n - k);
      if (sse < best) best = sse, split = k;
    }
    const double above = s1[split] / split, below = (s1[n] - s1[split]) / (n - split);
    if (split < n && std::abs(above - below) > 0.1 * above + 5) end = std::min(end, split);
  }
  return std::vector<int>(rows.begin(), rows.begin() + end);
}

// Where the reference's markers put things (image pixels).
struct Layout {
  double n, mid, y_low, e_px, h, cy, off;
  int x0, width;  // the columns searched
};

// The silhouette from every row the straight reference shows it on (between the upper and the
// lower markers, and below them): a first estimate of both edges, and the column profile of the
// rows between the markers (`between`, from column g.x0).
bool FirstSilhouette(const cv::Mat& gray, const Layout& g, double upper_y, double* left,
                     double* right, std::vector<double>* between, std::string* message) {
  EdgeBand first[2];
  first[0].rows =
      RowRange(upper_y + 0.7 * g.h + 2, g.y_low - 0.7 * g.h - 0.15 * g.off - 2, gray.rows);
  first[1].rows =
      RowRange(g.y_low + 0.7 * g.h + 0.1 * g.off + 2, g.y_low + 1.6 * g.e_px, gray.rows);
  std::vector<std::vector<double>> profiles(2);
  for (int b = 0; b < 2; ++b) ColumnProfile(gray, first[b].rows, g.x0, g.width, &profiles[b]);
  int li = 0, ri = 0;
  // The lower markers lie on the surface: each edge lies beyond the nearer marker's centre.
  if (first[0].rows.size() + first[1].rows.size() < 4 ||
      !SilhouetteEdges(profiles, g.x0, g.mid, 0.5 * g.n + 1.5, 1.7 * g.n, &li, &ri)) {
    *message = "the joint shows too few rows beside its markers to find its silhouette";
    return false;
  }
  for (int b = 0; b < 2; ++b) MeasureBand(gray, g.x0, g.width, li, ri, &first[b], &profiles[b]);
  *left = MeanEdge(first, 0);
  *right = MeanEdge(first, 1);
  const bool faint = first[0].strength[0] == 0 && first[1].strength[0] == 0 &&
                     first[0].strength[1] == 0 && first[1].strength[1] == 0;
  if (std::isnan(*left) || std::isnan(*right) || faint) {
    *message =
        "the joint's silhouette does not stand out from the background around the lower "
        "markers";
    return false;
  }
  *between = std::move(profiles[0]);
  return true;
}

// The rows the lower markers can reach (turned, they recede towards the horizon row), and the
// bands above (below where a bent upper part can reach: 1.15 radii below the pivot) and below
// them that show only the surface.
bool ChooseBands(const cv::Mat& gray, const Layout& g, const CylinderView& cyl, double left,
                 double right, LowerCalibration* cal, std::string* message) {
  // A lower marker turned to theta moves along its row's line to the principal row by the ratio
  // of its depths: each marker's rows, over every turn it can be read at (and a little beyond,
  // up to 80 degrees), plus its half-height at that depth and a pixel for a camera tilted a
  // little (its horizon row is not quite the principal row).
  double top = g.y_low, bottom = g.y_low;
  for (double x : {g.mid - 0.5 * g.n, g.mid + 0.5 * g.n}) {
    const double depth0 = cyl.Depth(cyl.ThetaFromX(x));
    for (double deg = -80; deg <= 80; deg += 2) {
      const double scale = depth0 / cyl.Depth(RadFromDeg(deg));
      const double y = g.cy + (g.y_low - g.cy) * scale;
      top = std::min(top, y - 0.5 * g.h * scale - 1);
      bottom = std::max(bottom, y + 0.5 * g.h * scale + 1);
    }
  }
  cal->band_top = std::max(0, static_cast<int>(std::floor(top)));
  cal->band_bottom = std::min(gray.rows - 1, static_cast<int>(std::ceil(bottom)));
  const double pivot_y = g.y_low - g.e_px;
  cal->bands[0].rows = RowRange(pivot_y + 1.15 * cyl.half_width_px(), cal->band_top - 2, gray.rows);
  const std::vector<int> below = RowRange(cal->band_bottom + 2, g.y_low + 1.6 * g.e_px, gray.rows);
  cal->bands[1].rows = RowsOnTheSurface(gray, below, left, right);
  if (cal->bands[0].rows.size() + cal->bands[1].rows.size() < 3) {
    cal->bands[1].rows = RowsBeforeTheEnd(gray, below, left, right);
  }
  if (cal->bands[0].rows.size() + cal->bands[1].rows.size() < 3) {
    *message = "the joint shows too few rows beside its markers to find its silhouette";
    return false;
  }
  return true;
}

// The rest of the calibration from a first silhouette (`left`, `right`): bands, edges, markers
// and limbs (CalibrateLowerPart's steps after the first silhouette).
bool CalibrateFromSilhouette(const cv::Mat& gray, const MarkerCamera& camera, const Layout& g,
                             cv::Point2d left_px, cv::Point2d right_px, cv::Point2d upper_px,
                             double left, double right, LowerCalibration* cal, LowerScan* scan,
                             std::string* message);

}  // namespace

bool CalibrateLowerPart(const cv::Mat& gray, const MarkerCamera& camera, cv::Point2d left_px,
                        cv::Point2d right_px, cv::Point2d upper_px, double marker_height_px,
                        LowerCalibration* cal, LowerScan* scan, std::string* message) {
  Layout g;
  g.n = right_px.x - left_px.x;
  g.mid = 0.5 * (left_px.x + right_px.x);
  g.y_low = 0.5 * (left_px.y + right_px.y);
  g.e_px = 0.5 * (g.y_low - upper_px.y);
  g.h = marker_height_px;
  g.cy = camera.principal_px.y;
  g.off = std::abs(g.y_low - g.cy);
  g.x0 = std::max(0, static_cast<int>(g.mid - 1.8 * g.n) - 4);
  g.width = std::min(gray.cols, static_cast<int>(g.mid + 1.8 * g.n) + 5) - g.x0;
  double left = 0, right = 0;
  std::vector<double> between;
  if (!FirstSilhouette(gray, g, upper_px.y, &left, &right, &between, message)) return false;
  const LowerCalibration given = *cal;
  if (CalibrateFromSilhouette(gray, camera, g, left_px, right_px, upper_px, left, right, cal, scan,
                              message)) {
    return AboutTheUpper(camera, upper_px, *cal, message);
  }
  // Tried only for a reference that the steps' silhouette leaves refused: a step that is the
  // far edge of the joint's own shadow (ShadowedLimb), moved to the limb.
  const std::string refused = *message;
  for (int side = 0; side < 2; ++side) {
    const double edge = ShadowedLimb(between, g.x0, side == 0 ? left : right, side,
                                     side == 0 ? left_px.x : right_px.x);
    if (std::isnan(edge)) continue;
    *cal = given;  // the scan starts afresh at the silhouette's edges (StartAtEdges)
    if (CalibrateFromSilhouette(gray, camera, g, left_px, right_px, upper_px,
                                side == 0 ? edge : left, side == 0 ? right : edge, cal, scan,
                                message)) {
      // The ramp's end is where the lit surface meets the shadow, which the limb's own dark
      // shading may already have reached: it sizes no single lower marker (a tuning rig's
      // single-marker yaws had come out 6 degrees off); two markers still check each other.
      cal->single_sized = false;
      return AboutTheUpper(camera, upper_px, *cal, message);
    }
  }
  *message = refused;
  return false;
}

namespace {

bool CalibrateFromSilhouette(const cv::Mat& gray, const MarkerCamera& camera, const Layout& g,
                             cv::Point2d left_px, cv::Point2d right_px, cv::Point2d upper_px,
                             double left, double right, LowerCalibration* cal, LowerScan* scan,
                             std::string* message) {
  const CylinderView cyl(camera, left, right);
  if (!cyl.valid()) {
    *message =
        "the joint's silhouette is too wide for the camera's field of view (check the field of "
        "view setting)";
    return false;
  }
  if (!ChooseBands(gray, g, cyl, left, right, cal, message)) return false;
  // Each band's own edges, and the surface's grey level per column from all of them.
  std::vector<double> surface(g.width, 0.0), profile;
  double rows = 0;
  for (EdgeBand& band : cal->bands) {
    MeasureBand(gray, g.x0, g.width, left, right, &band, &profile);
    for (int i = 0; i < g.width; ++i) surface[i] += band.rows.size() * profile[i];
    rows += band.rows.size();
  }
  for (double& v : surface) v /= rows;
  const EdgeBand* bands = cal->bands;
  if (bands[0].strength[0] == 0 && bands[1].strength[0] == 0 && bands[0].strength[1] == 0 &&
      bands[1].strength[1] == 0) {
    *message = "the joint's silhouette does not stand out from the background";
    return false;
  }
  cal->left_edge_px = MeanEdge(bands, 0);
  cal->right_edge_px = MeanEdge(bands, 1);
  // A faint edge may be placed on the surface's shading near the limb instead, and bands that
  // disagree (a silhouette is one column) show an edge caught on something else: such a side
  // (the weaker, if both) is checked against where the reference's lower markers lie
  // symmetrically about the upper one, and moved there when more than a pixel off.
  auto unsure = [&](int side) {
    const bool both = bands[0].strength[side] != 0 && bands[1].strength[side] != 0;
    return cal->steepest(side) < kPlain ||
           (both && std::abs(bands[0].edge_px[side] - bands[1].edge_px[side]) > 1);
  };
  int weak = cal->steepest(0) < cal->steepest(1) ? 0 : 1;
  if (unsure(1 - weak) && !unsure(weak)) weak = 1 - weak;
  // The edge tried second for the weak side: the markers' symmetry after a faint step's own
  // edge, or the step no band tracks after the symmetry.
  double second_edge = kNaN;
  if (unsure(weak)) {
    const double known = weak == 0 ? cal->right_edge_px : cal->left_edge_px;
    const double edge = HiddenEdge(camera, known, weak, left_px, right_px, upper_px);
    double& fitted = weak == 0 ? cal->left_edge_px : cal->right_edge_px;
    // The markers' symmetry places an edge no step shows. It is only approximate (under side
    // light, seen from aside or by a tilted camera a marker's centroid is not its centre's
    // image, and the upper marker lies at another height): a faint step's own edge is tried
    // before it, and EqualDiscs refines whichever shows both lower markers whole.
    // A side no band tracks (a step under kTrackable) is placed by the symmetry, and the step
    // the first silhouette found there from all rows is tried after it (seen from aside, with a
    // lower marker near the limb, the symmetry had put an edge 45 px out). Without the
    // symmetry's edge the side is refused: the step alone had let a triple of wall blobs
    // calibrate.
    if (!std::isnan(edge)) {
      if (cal->steepest(weak) == 0) {
        if (std::abs(edge - fitted) > 1) second_edge = fitted;
        fitted = edge;
      } else if (std::abs(edge - fitted) > 1 && cal->steepest(weak) < kPlain) {
        second_edge = edge;
      }
    } else if (cal->steepest(weak) == 0) {
      *message = "the joint's silhouette does not stand out from the background on one side";
      return false;
    }
  }
  cal->search_px = std::max(3, static_cast<int>(std::lround(0.1 * (right - left))));
  cal->marker_height_px = g.h;
  // At zero yaw both lower markers show whole, near a limb as they may be: a silhouette that
  // cuts one is wrong. The steps' own edges are tried first, then the faint edge placed by the
  // markers' symmetry; a marker cut by the limb is accepted only when neither shows both whole.
  const double fitted_edges[2] = {cal->left_edge_px, cal->right_edge_px};
  // Every row that shows the straight joint's limbs beside the markers: from below the upper
  // marker down to the marker band, and the band below it.
  std::vector<int> limb_rows = RowRange(
      upper_px.y + 0.7 * g.h + 2,
      std::min<double>(g.y_low - 0.7 * g.h - 0.15 * g.off - 2, cal->band_top - 2), gray.rows);
  limb_rows.insert(limb_rows.end(), cal->bands[1].rows.begin(), cal->bands[1].rows.end());
  std::string first_message;
  for (int attempt = 0; attempt < 4; ++attempt) {
    const bool moved = attempt % 2 == 1;
    if (moved && std::isnan(second_edge)) continue;
    double edges[2] = {fitted_edges[0], fitted_edges[1]};
    if (moved) edges[weak] = second_edge;
    StartAtEdges(camera, edges[0], edges[1], cal, scan);
    if (MeasureReferenceMarkers(gray, camera, g.x0, surface, attempt >= 2, cal, scan, message)) {
      // A plain step that the bands agree on is the silhouette: only an unsure edge is moved.
      if (unsure(weak)) EqualDiscs(gray, camera, g.x0, surface, weak, cal, scan);
      const bool plain[2] = {!unsure(0), !unsure(1)};
      bool either_fitted = false;
      cal->single_sized = RefineLimbs(gray, camera, g.x0, surface, limb_rows, g.y_low, plain, cal,
                                      scan, &either_fitted);
      // Neither limb fits within reach of its step: the silhouette (or the triple) is something
      // else; the next attempt is tried, and the reference refused when none is left.
      if (!either_fitted) {
        *message = "neither limb of the joint fits the rows beside its markers";
        if (first_message.empty()) first_message = *message;
        continue;
      }
      // The step no band tracks, tried after the symmetry, is kept only when both limbs fit and
      // confirm the silhouette (a faint step alone had let a triple of wall blobs calibrate),
      // and even then sizes no single lower marker: the markers' symmetry disagrees with it, so
      // the zero-yaw angles may be degrees off (single-marker yaws 3-5 degrees off where
      // tried); two markers still check each other.
      if (moved && cal->steepest(weak) == 0) {
        if (!cal->single_sized) {
          *message = "the joint's silhouette does not stand out from the background on one side";
          if (first_message.empty()) first_message = *message;
          continue;
        }
        cal->single_sized = false;
        return true;
      }
      // ... or, as before, both lower markers whole and equal discs.
      const LowerMarker& l = scan->markers[0];
      const LowerMarker& r = scan->markers[1];
      cal->single_sized |=
          !l.cut && !r.cut && std::abs(l.radius - r.radius) <= kEqualDiscs * (l.radius + r.radius);
      return true;
    }
    if (first_message.empty()) first_message = *message;
  }
  *message = first_message;
  return false;
}

}  // namespace

}  // namespace armmimic::internal
