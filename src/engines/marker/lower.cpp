// The lower part of the marker joint in one image (docs/marker.md, "The cylinder model").
//
// Silhouette: the lower part is upright and the camera level, so its edges are image columns;
// the mean of the bands of rows above and below the markers gives a column profile with little
// noise, whose steepest steps near the reference's edges are the silhouette. Shading: Lambertian
// shading of an upright cylinder under a distant light depends on the column only, so the same
// profile is the surface's grey level in the marker band, and marker coverage there is
// (surface - grey) / (surface * (1 - marker ratio)). Markers: each row of a patch covers an
// interval whose ends follow from the row's coverage sum and first moment; mapped to surface
// angles, the interval's middle is the marker centre's angle (the disc is symmetric in arc
// length), or, when the limb cuts the far end, the inner end plus the disc's half-chord.
// Length: FitPatch is one least-squares fit whose row sums feed each following step.
#include "marker/lower.h"

#include <algorithm>
#include <cmath>

#include "armmimic/core/angles.h"

namespace armmimic::internal {
namespace {

constexpr double kEdgeNoisePx = 0.12;   // spread of one row's interval end, pixels
constexpr double kCommonEdgePx = 0.04;  // ... shared by every row of a patch
constexpr double kCutEdgePx = 0.3;      // ... for an end within kNearLimbPx of the limb
constexpr double kNearLimbPx = 1.5;
constexpr double kChordSpread = 0.004;     // radians: the half-chord from the reference's radius
constexpr double kShiftAgreementPx = 0.5;  // edges whose shifts agree this well move together

// Coverage rows of the band: [band_top, band_bottom], columns [x0, x0 + width).
struct CoverageBand {
  const float* data = nullptr;
  int x0 = 0, width = 0, top = 0, rows = 0;
  float at(int x, int y) const { return data[(y - top) * width + (x - x0)]; }
};

// Fits one patch of columns [c0, c1]. False when it does not look like a marker.
bool FitPatch(const CoverageBand& band, const CylinderView& cyl, const LowerCalibration& cal,
              double left_edge, double right_edge, int c0, int c1, bool calibrating,
              LowerMarker* out) {
  const int rows = band.rows;
  std::vector<double> w(rows, 0), m(rows, 0);
  double total = 0, ysum = 0, wmax = 0;
  for (int r = 0; r < rows; ++r) {
    for (int x = c0; x <= c1; ++x) {
      const double c = band.at(x, band.top + r);
      w[r] += c;
      m[r] += c * x;
    }
    if (w[r] > 0.3) {
      total += w[r];
      ysum += w[r] * (band.top + r);
    }
    wmax = std::max(wmax, w[r]);
  }
  if (total < 2 || wmax < 0.8) return false;
  const double yc = ysum / total;
  const double theta_guess = cyl.ThetaFromX(0.5 * (c0 + c1));
  // Arc length (radii) per image row at the patch.
  const double row_arc = cyl.Depth(theta_guess) / cyl.camera().focal_px;
  int n = 0, cut_left = 0, cut_right = 0;
  struct RowEnds {
    double a, b, v;
  };
  std::vector<RowEnds> ends;
  for (int r = 0; r < rows; ++r) {
    if (w[r] < 0.6 * wmax) continue;
    const double mid = m[r] / w[r];
    const RowEnds e{mid - 0.5 * w[r], mid + 0.5 * w[r], (band.top + r - yc) * row_arc};
    ends.push_back(e);
    cut_left += e.a < left_edge + 0.6;
    cut_right += e.b > right_edge - 0.6;
    ++n;
  }
  if (n == 0) return false;
  const bool cut_l = 3 * cut_left > n, cut_r = 3 * cut_right > n;
  if (cut_l && cut_r) return false;
  // Two readings of the centre's angle per row: the middle of the interval's ends, and the inner
  // end (the one nearer the front) plus the disc's half-chord at that row, the only one when the
  // limb cuts the far end. Near a limb an end's angle changes fast with the column and the edge
  // pixel's mixture is least sure; the reading with the smaller expected spread is used.
  struct Reading {
    double sum = 0, noise = 0, common = 0;  // angles, and the spreads' squares, summed
    int n = 0;
    double Spread() const { return std::sqrt(noise / n / n + common / n); }
  } middle, inner;
  const bool inner_is_left = cut_r || (!cut_l && theta_guess > 0);
  double delta2_sum = 0;
  for (const RowEnds& e : ends) {
    const double ta = cyl.ThetaFromX(e.a), tb = cyl.ThetaFromX(e.b);
    const double sa = cyl.ThetaSlope(e.a), sb = cyl.ThetaSlope(e.b);
    const double ca = e.a < left_edge + kNearLimbPx ? kCutEdgePx : kCommonEdgePx;
    const double cb = e.b > right_edge - kNearLimbPx ? kCutEdgePx : kCommonEdgePx;
    if (!cut_l && !cut_r) {
      middle.sum += 0.5 * (ta + tb);
      middle.noise += 0.25 * (sa * sa + sb * sb) * kEdgeNoisePx * kEdgeNoisePx;
      middle.common += 0.25 * (sa * sa * ca * ca + sb * sb * cb * cb);
      ++middle.n;
      delta2_sum += 0.25 * (tb - ta) * (tb - ta) + e.v * e.v;
    }
    if (cal.delta > 0 && std::abs(e.v) <= 0.8 * cal.delta) {
      const double half = std::sqrt(cal.delta * cal.delta - e.v * e.v);
      const double s = inner_is_left ? sa : sb, c = inner_is_left ? ca : cb;
      inner.sum += inner_is_left ? ta + half : tb - half;
      inner.noise += s * s * kEdgeNoisePx * kEdgeNoisePx;
      inner.common += s * s * c * c + kChordSpread * kChordSpread;
      ++inner.n;
    }
  }
  const bool use_middle = middle.n > 0 && (inner.n == 0 || middle.Spread() <= inner.Spread());
  const Reading& r = use_middle ? middle : inner;
  if (r.n == 0) return false;
  out->theta = r.sum / r.n;
  out->sigma = r.Spread();
  out->cut = cut_l || cut_r;
  out->first_col = c0;
  out->last_col = c1;
  out->coverage_px = total;
  out->centre_px = {cyl.XFromTheta(out->theta), yc};
  out->radius = middle.n > 0 ? std::sqrt(delta2_sum / middle.n) : kNaN;
  // In calibration a cut marker is kept once the markers' angular radius is known (from the
  // whole one), which its reading rests on.
  if (calibrating) return !out->cut || cal.delta > 0;
  // A disc of the markers' size, not a shadow or a fleck.
  if (!out->cut && (out->radius < 0.7 * cal.delta || out->radius > 1.35 * cal.delta)) return false;
  // The markers' height is known: a patch elsewhere in the band is something else.
  const double expected_y =
      cyl.camera().principal_px.y - cyl.camera().focal_px * cal.height / cyl.Depth(out->theta);
  return std::abs(yc - expected_y) <= 0.4 * cal.marker_height_px + 1.5;
}

// The step in `profile` (first column x0) nearest to `peak_px` within `search` pixels whose
// gradient has the sign of `strength` and at least 0.4 of its size: the joint does not move
// between views (a camera may shake a little), so the reference's own step, when it still shows
// as a step, is preferred to a steeper one beside it (the bent upper part's shadow on the wall).
ProfileEdge NearestStep(const std::vector<double>& profile, int x0, double peak_px, int search,
                        double strength) {
  const int n = static_cast<int>(profile.size());
  const int sign = strength > 0 ? 1 : -1;
  const double need = 0.4 * std::abs(strength);
  auto g = [&](int i) { return sign * 0.5 * (profile[i + 1] - profile[i - 1]); };
  const int centre = static_cast<int>(std::lround(peak_px)) - x0;
  int best = -1;
  for (int i = std::max(2, centre - search); i <= std::min(n - 3, centre + search); ++i) {
    if (g(i) < need || g(i) < g(i - 1) || g(i) < g(i + 1)) continue;  // a local peak, steep enough
    if (best < 0 || std::abs(i - centre) < std::abs(best - centre)) best = i;
  }
  if (best < 0) return ProfileEdge();
  return FindProfileEdge(profile, x0, best, best, sign);
}

}  // namespace

void MeasureLowerMarkers(const cv::Mat& gray, const LowerCalibration& cal, int x0,
                         const std::vector<double>& surface, bool calibrating, LowerScan* out,
                         LowerScratch* s) {
  const double xl = out->left_edge_px, xr = out->right_edge_px;
  const int c0 = std::max(0, static_cast<int>(std::ceil(xl - 0.5)));
  const int c1 = std::min(gray.cols - 1, static_cast<int>(std::floor(xr + 0.5)));
  const int width = c1 - c0 + 1;
  const int rows = cal.band_bottom - cal.band_top + 1;
  out->first_col = c0;
  out->column_coverage.assign(std::max(0, width), 0.0);
  out->markers.clear();
  if (width < 4 || rows < 2) return;
  s->coverage.assign(static_cast<std::size_t>(width) * rows, 0.f);
  const double keep = 1 - cal.marker_ratio;
  // The two edge pixels hold background too, which differs from row to row: their surface share
  // phi and the surface's own level there come from the profile, the background from the pixel
  // beside them in the same row.
  const double phi[2] = {c0 + 0.5 - xl, xr - (c1 - 0.5)};
  double limb[2] = {0, 0};
  for (int side = 0; side < 2; ++side) {
    const int x = side == 0 ? c0 : c1, out_x = side == 0 ? c0 - 1 : c1 + 1;
    if (phi[side] < 0.2 || out_x - x0 < 0 || out_x - x0 >= static_cast<int>(surface.size())) {
      continue;
    }
    limb[side] = (surface[x - x0] - (1 - phi[side]) * surface[out_x - x0]) / phi[side];
  }
  for (int r = 0; r < rows; ++r) {
    const uchar* row = gray.ptr<uchar>(cal.band_top + r);
    float* dst = &s->coverage[static_cast<std::size_t>(r) * width];
    for (int i = 0; i < width; ++i) {
      double p = surface[c0 + i - x0], range = p * keep, v = row[c0 + i], floor = 8, share = 1;
      if (i == 0 || i == width - 1) {
        const int side = i == 0 ? 0 : 1, out_x = side == 0 ? c0 - 1 : c1 + 1;
        if (limb[side] <= 0 || out_x < 0 || out_x >= gray.cols) continue;
        p = phi[side] * limb[side];
        range = p * keep;
        v -= (1 - phi[side]) * row[out_x];
        floor *= phi[side];
        share = phi[side];  // coverage of the whole pixel
      }
      if (range < floor) continue;  // too dark to tell a marker from the surface
      // Not clamped at 0: noise on a dark surface would otherwise add up down each column.
      const double c = share * std::clamp((p - v) / range, -0.5, 1.1);
      dst[i] = static_cast<float>(c);
      out->column_coverage[i] += c;
    }
  }
  const CoverageBand band{s->coverage.data(), c0, width, cal.band_top, rows};
  // Patches: runs of columns holding at least a tenth of a marker's height of marker, one of
  // them a fifth, widened by a column either side for the antialiased ends.
  const double lo = std::max(0.5, 0.1 * cal.marker_height_px);
  const double hi = std::max(1.0, 0.2 * cal.marker_height_px);
  for (int i = 0; i < width;) {
    if (out->column_coverage[i] < lo) {
      ++i;
      continue;
    }
    int j = i;
    double peak = 0;
    while (j < width && out->column_coverage[j] >= lo)
      peak = std::max(peak, out->column_coverage[j++]);
    if (peak >= hi) {
      LowerMarker mk;
      if (FitPatch(band, out->cylinder, cal, xl, xr, c0 + std::max(0, i - 1),
                   c0 + std::min(width - 1, j), calibrating, &mk)) {
        out->markers.push_back(mk);
      }
    }
    i = j;
  }
}

double LowerScan::CoverageBetween(double x0, double x1, const LowerMarker* skip) const {
  double sum = 0;
  const int a = std::max(0, static_cast<int>(std::floor(std::min(x0, x1))) - first_col);
  const int b = std::min(static_cast<int>(column_coverage.size()) - 1,
                         static_cast<int>(std::ceil(std::max(x0, x1))) - first_col);
  for (int i = a; i <= b; ++i) {
    const int x = first_col + i;
    if (skip && x >= skip->first_col && x <= skip->last_col) continue;
    sum += column_coverage[i];
  }
  return sum;
}

bool ScanLowerPart(const cv::Mat& gray, const LowerCalibration& cal, const MarkerCamera& camera,
                   LowerScan* out, LowerScratch* s) {
  *out = LowerScan();
  const int x0 = std::max(0, static_cast<int>(cal.left_edge_px) - cal.search_px - 4);
  const int x1 = std::min(gray.cols, static_cast<int>(cal.right_edge_px) + cal.search_px + 5);
  const int width = x1 - x0;
  std::vector<double>* profiles[2] = {&s->above, &s->below};
  // Each edge in each band, kept when about as strong as in the reference; its shift from the
  // reference's position in that band. Bands that disagree with the strongest one are left out.
  double rows = 0;
  double band_shift[2][2] = {{kNaN, kNaN}, {kNaN, kNaN}};
  s->surface.assign(width, 0.0);
  for (int b = 0; b < 2; ++b) {
    const EdgeBand& band = cal.bands[b];
    if (band.rows.empty()) continue;
    ColumnProfile(gray, band.rows, x0, width, profiles[b]);
    const double n = static_cast<double>(band.rows.size());
    for (int i = 0; i < width; ++i) s->surface[i] += n * (*profiles[b])[i];
    rows += n;
    for (int side = 0; side < 2; ++side) {
      if (band.strength[side] == 0) continue;
      const ProfileEdge e =
          NearestStep(*profiles[b], x0, band.peak_px[side], cal.search_px, band.strength[side]);
      if (e.found) band_shift[side][b] = e.x - band.peak_px[side];
    }
  }
  // The lower part is rigid: every edge of every band shows the same shift. The shift most of
  // them agree on (within half a pixel; the steeper steps when as many agree on two) is taken,
  // as their weighted mean: an edge caught on something else (the bent upper part's shadow
  // beside a limb) is outvoted.
  double value[4], weight[4];
  int n = 0;
  for (int side = 0; side < 2; ++side) {
    for (int b = 0; b < 2; ++b) {
      if (std::isnan(band_shift[side][b])) continue;
      value[n] = band_shift[side][b];
      weight[n++] =
          cal.bands[b].rows.size() * cal.bands[b].strength[side] * cal.bands[b].strength[side];
    }
  }
  if (n == 0) {
    out->failure = "the joint's silhouette is not where the reference shows it";
    return false;
  }
  for (double& v : s->surface) v /= rows;
  int best_count = 0;
  double best_weight = 0, common = 0;
  for (int i = 0; i < n; ++i) {
    int count = 0;
    double w = 0, sum = 0;
    for (int j = 0; j < n; ++j) {
      if (std::abs(value[j] - value[i]) > kShiftAgreementPx) continue;
      ++count;
      w += weight[j];
      sum += weight[j] * value[j];
    }
    if (count > best_count || (count == best_count && w > best_weight)) {
      best_count = count, best_weight = w, common = sum / w;
    }
  }
  double shift[2] = {common, common};
  out->left_edge_px = cal.left_edge_px + shift[0];
  out->right_edge_px = cal.right_edge_px + shift[1];
  out->cylinder = CylinderView(camera, out->left_edge_px, out->right_edge_px);
  if (!out->cylinder.valid()) {
    out->failure = "the joint's silhouette edges cross";
    return false;
  }
  MeasureLowerMarkers(gray, cal, x0, s->surface, false, out, s);
  return true;
}

}  // namespace armmimic::internal
