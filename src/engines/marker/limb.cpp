// One limb fitted over every row that shows it (docs/marker.md, "Calibration", step 2): rows in
// groups of two, each group's profile across the limb; the limb a line x = x0 + lean (y - y_ref);
// each group's pixels modelled as its own wall (level and slope) beyond the limb and the shared
// surface p + q sqrt(d) + r d at distance d inside it, the pixel's box blurred by the lens. The
// lean comes from the groups' steepest steps (a robust line), then the limb's column from the
// least misfit; groups that fit far worse than the others (a shadow's edge next to the limb)
// are left out and the column searched again.
// Length: FitLimb's search shares the groups' profiles and the solve over the candidates.
#include "marker/limb.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "marker/cylinder.h"

namespace armmimic::internal {
namespace {

constexpr int kGroupRows = 2;
constexpr int kOutside = 4, kInside = 8;
constexpr double kBlurPx = 0.5;  // the lens' blur the model assumes (a Gaussian's sigma, pixels)
constexpr double kMaxLean =
    0.06;  // columns per row: a camera tilted 7 degrees, the joint at a side

struct Group {
  double y = 0;                // mean row
  std::vector<double> values;  // columns [c0, c0 + values.size())
  int c0 = 0;
  double step_x = 0, step = 0;  // steepest step near the guess
  bool used = true;
};

// The surface's three basis functions and the wall's two at signed distance d into the joint,
// averaged over a pixel [lo, hi] blurred by kBlurPx.
void PixelBasis(double lo, double hi, double* surface, double* wall) {
  constexpr int kSub = 6;
  constexpr double kTaps[5] = {-2, -1, 0, 1, 2};
  constexpr double kWeights[5] = {0.0545, 0.2442, 0.4026, 0.2442, 0.0545};
  for (int k = 0; k < 3; ++k) surface[k] = 0;
  wall[0] = wall[1] = 0;
  for (int s = 0; s < kSub; ++s) {
    const double d0 = lo + (s + 0.5) * (hi - lo) / kSub;
    for (int j = 0; j < 5; ++j) {
      const double d = d0 + kTaps[j] * kBlurPx, w = kWeights[j] / kSub;
      if (d > 0) {
        surface[0] += w;
        surface[1] += w * std::sqrt(d);
        surface[2] += w * d;
      } else {
        wall[0] += w;
        wall[1] += w * d;
      }
    }
  }
}

// The basis of every pixel near the limb, for the limb's position within its pixel quantised to
// 1/kFractions: table[f][k] for the pixel k - kOutside - 1 columns from the limb's pixel.
constexpr int kFractions = 50, kSpan = kOutside + kInside + 3;
struct BasisTable {
  std::array<std::array<std::array<double, 5>, kSpan>, kFractions> at;
  explicit BasisTable(int inside) {
    for (int f = 0; f < kFractions; ++f) {
      const double frac = (f + 0.5) / kFractions;
      for (int k = 0; k < kSpan; ++k) {
        const int dx = k - kOutside - 1;
        const double e0 = inside * (dx - 0.5 - frac), e1 = inside * (dx + 0.5 - frac);
        double sb[3], wb[2];
        PixelBasis(std::min(e0, e1), std::max(e0, e1), sb, wb);
        at[f][k] = {sb[0], sb[1], sb[2], wb[0], wb[1]};
      }
    }
  }
};

// Least misfit of all used groups for the limb at x0 + lean (y - y_ref); per group misfits in
// `per_group` when given.
double Misfit(const std::vector<Group>& groups, const BasisTable& table, double x0, double lean,
              double y_ref, int inside, std::vector<double>* per_group) {
  // Shared: the surface's 1, sqrt(d) and d terms; each group's own: its wall's level and slope.
  cv::Matx33d a_ss = cv::Matx33d::zeros();
  cv::Vec3d b_s(0, 0, 0);
  double group_sse = 0;
  struct Block {
    cv::Matx<double, 3, 2> a_sb;
    cv::Matx22d a_bb_inv;
    cv::Vec2d b_b;
    std::vector<std::array<double, 6>> rows;  // shared basis (3), own basis (2), value
  };
  std::vector<Block> blocks;
  blocks.reserve(groups.size());
  for (const Group& g : groups) {
    if (!g.used) continue;
    const double t = x0 + lean * (g.y - y_ref);
    Block blk;
    blk.a_sb = cv::Matx<double, 3, 2>::zeros();
    cv::Matx22d a_bb = cv::Matx22d::zeros();
    blk.b_b = cv::Vec2d(0, 0);
    double yy = 0;
    const int n = static_cast<int>(g.values.size());
    const int base = static_cast<int>(std::floor(t));
    const int f = std::clamp(static_cast<int>((t - base) * kFractions), 0, kFractions - 1);
    for (int k = 0; k < kSpan; ++k) {
      const int dx = k - kOutside - 1;
      if (inside * dx < -kOutside || inside * dx > kInside) continue;
      const int i = base + dx - g.c0;
      if (i < 0 || i >= n) continue;
      const std::array<double, 5>& bs = table.at[f][k];
      const double sh[3] = {bs[0], bs[1], bs[2]}, own[2] = {bs[3], bs[4]};
      const double v = g.values[i];
      if (per_group) blk.rows.push_back({sh[0], sh[1], sh[2], own[0], own[1], v});
      for (int p = 0; p < 3; ++p) {
        for (int q = 0; q < 3; ++q) a_ss(p, q) += sh[p] * sh[q];
        for (int q = 0; q < 2; ++q) blk.a_sb(p, q) += sh[p] * own[q];
        b_s[p] += sh[p] * v;
      }
      for (int p = 0; p < 2; ++p) {
        for (int q = 0; q < 2; ++q) a_bb(p, q) += own[p] * own[q];
        blk.b_b[p] += own[p] * v;
      }
      yy += v * v;
    }
    a_bb(0, 0) += 1e-6;
    a_bb(1, 1) += 1e-6;
    blk.a_bb_inv = a_bb.inv();
    a_ss -= blk.a_sb * blk.a_bb_inv * blk.a_sb.t();
    b_s -= blk.a_sb * (blk.a_bb_inv * blk.b_b);
    group_sse += yy - blk.b_b.dot(blk.a_bb_inv * blk.b_b);
    blocks.push_back(std::move(blk));
  }
  cv::Vec3d xs;
  if (!cv::solve(a_ss, b_s, xs, cv::DECOMP_SVD)) return 1e300;
  const double sse = group_sse - xs.dot(b_s);
  if (per_group) {
    per_group->clear();
    for (const Block& blk : blocks) {
      const cv::Vec2d wb = blk.a_bb_inv * (blk.b_b - blk.a_sb.t() * xs);
      double e = 0;
      for (const auto& r : blk.rows) {
        const double m = r[0] * xs[0] + r[1] * xs[1] + r[2] * xs[2] + r[3] * wb[0] + r[4] * wb[1];
        e += (m - r[5]) * (m - r[5]);
      }
      per_group->push_back(e / std::max<std::size_t>(1, blk.rows.size()));
    }
  }
  return sse;
}

}  // namespace

LimbFit FitLimb(const cv::Mat& gray, const std::vector<int>& rows, double x_guess, double y_ref,
                int inside, double range) {
  LimbFit out;
  std::vector<Group> groups;
  const int margin = static_cast<int>(std::ceil(range)) + kOutside + kInside + 3;
  const int c0 = std::max(0, static_cast<int>(std::floor(x_guess)) - margin);
  const int c1 = std::min(gray.cols - 1, static_cast<int>(std::ceil(x_guess)) + margin);
  if (c1 - c0 < 2 * kInside) return out;
  for (std::size_t i = 0; i + kGroupRows <= rows.size(); i += kGroupRows) {
    Group g;
    g.c0 = c0;
    g.values.assign(c1 - c0 + 1, 0.0);
    for (int k = 0; k < kGroupRows; ++k) {
      const uchar* row = gray.ptr<uchar>(rows[i + k]);
      for (int x = c0; x <= c1; ++x) g.values[x - c0] += row[x];
      g.y += rows[i + k];
    }
    for (double& v : g.values) v /= kGroupRows;
    g.y /= kGroupRows;
    const ProfileEdge e = FindProfileEdge(g.values, c0, static_cast<int>(x_guess - range) - c0,
                                          static_cast<int>(x_guess + range) + 1 - c0, 0);
    if (!e.found) continue;
    g.step_x = e.x;
    g.step = std::abs(e.strength);
    groups.push_back(std::move(g));
  }
  if (groups.size() < 4) return out;
  const BasisTable table(inside);
  double best_x = x_guess, best_lean = 0;
  auto search = [&](double x_from, double x_to, double x_step, double l_from, double l_to,
                    double l_step) {
    double best_sse = 1e300;
    const double x_centre = best_x, l_centre = best_lean;
    for (double l = l_centre + l_from; l <= l_centre + l_to + 1e-9; l += l_step) {
      for (double x = x_centre + x_from; x <= x_centre + x_to + 1e-9; x += x_step) {
        const double sse = Misfit(groups, table, x, l, y_ref, inside, nullptr);
        if (sse < best_sse) best_sse = sse, best_x = x, best_lean = l;
      }
    }
  };
  search(-range, range, 0.1, -kMaxLean, kMaxLean, 0.005);
  search(-0.1, 0.1, 0.02, -0.005, 0.005, 0.001);
  // Groups that fit far worse than the rest are something else beside the limb.
  std::vector<double> per_group;
  Misfit(groups, table, best_x, best_lean, y_ref, inside, &per_group);
  std::vector<double> sorted = per_group;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  int kept = 0;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    groups[i].used = per_group[i] <= 4 * median + 1;
    kept += groups[i].used;
  }
  if (kept < 4) return out;
  search(-0.5, 0.5, 0.05, -0.01, 0.01, 0.002);
  search(-0.05, 0.05, 0.01, -0.002, 0.002, 0.0005);
  const double sse = Misfit(groups, table, best_x, best_lean, y_ref, inside, nullptr);
  const double x = best_x, lean = best_lean;
  // A best fit at the end of the search is the surface's own shading fitted as the wall (or the
  // wall's as the surface): no limb there.
  if (std::abs(x - x_guess) > range - 0.3) return out;
  out.ok = true;
  out.x = x;
  out.lean = lean;
  out.groups = kept;
  out.rms = std::sqrt(std::max(0.0, sse) / std::max(1, kept * (kOutside + kInside)));
  return out;
}

}  // namespace armmimic::internal
