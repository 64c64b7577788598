// Marker candidates, sub-pixel centres and the choice of the three markers (docs/marker.md).
// Length: RefineMarker grows, thresholds and measures one window; the steps share the window and
// its statistics.
#include "marker/detect.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"

namespace armmimic::internal {
namespace {

cv::Point2d BoxCentre(const cv::Rect& r) {
  return {r.x + (r.width - 1) / 2.0, r.y + (r.height - 1) / 2.0};
}

int Find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

void MonoImage(const cv::Mat& bgr, MarkerChannel channel, cv::Mat* out) {
  if (bgr.channels() == 1) {
    bgr.copyTo(*out);
  } else if (channel == MarkerChannel::kLuma) {
    cv::cvtColor(bgr, *out, cv::COLOR_BGR2GRAY);
  } else {
    cv::extractChannel(bgr, *out, static_cast<int>(channel) - 1);
  }
}

const char* ChannelName(MarkerChannel channel) {
  switch (channel) {
    case MarkerChannel::kLuma:
      return "luma";
    case MarkerChannel::kBlue:
      return "blue";
    case MarkerChannel::kGreen:
      return "green";
    case MarkerChannel::kRed:
      return "red";
  }
  return "luma";
}

void MedianWhereDark(const cv::Mat& gray, int ksize, int high, cv::Mat* out, cv::Mat* band_out) {
  out->create(gray.size(), CV_8UC1);
  out->setTo(255);
  const int r = ksize / 2;
  constexpr int kBand = 32;  // rows; full-width bands keep the filter's vector loops long
  const cv::Rect image(0, 0, gray.cols, gray.rows);
  for (int y = 0; y < gray.rows; y += kBand) {
    const cv::Rect band = cv::Rect(0, y, gray.cols, kBand) & image;
    const cv::Rect crop = cv::Rect(0, band.y - r, gray.cols, band.height + 2 * r) & image;
    double darkest = 0;
    cv::minMaxLoc(gray(crop), &darkest);
    if (darkest > high) continue;  // no window here holds a pixel <= high
    MedianFilter(gray(crop), ksize, band_out);
    (*band_out)(cv::Rect(0, band.y - crop.y, band.width, band.height)).copyTo((*out)(band));
  }
}

void MarkerImages(const cv::Mat& bgr, const MarkerOptions& options, MarkerScratch* s) {
  MonoImage(bgr, MarkerChannel::kLuma, &s->gray);
  MedianWhereDark(s->gray, options.median_size, options.high, &s->filtered, &s->tile);
}

std::vector<MarkerBlob> FindMarkerCandidates(const cv::Mat& bgr, const MarkerOptions& options,
                                             MarkerScratch* s) {
  MarkerImages(bgr, options, s);
  s->components =
      FloodFillComponents(s->filtered, options.low, options.high, options.flood_range, &s->labels);
  const double scale = static_cast<double>(bgr.cols) * bgr.rows / (320.0 * 240.0);
  const double min_area = options.min_area * scale;
  const double max_area = options.max_area * scale;

  // A marker's antialiased rim seeds components of its own (the range is relative to the seed):
  // small components whose boxes mostly overlap are fragments of one blob and are merged.
  std::vector<int> small;
  for (int i = 0; i < static_cast<int>(s->components.size()); ++i) {
    const Component& c = s->components[i];
    if (c.area_px <= max_area && c.box.area() <= 4 * max_area) small.push_back(i);
  }
  std::sort(small.begin(), small.end(),
            [&](int a, int b) { return s->components[a].box.x < s->components[b].box.x; });
  std::vector<int> parent(small.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < small.size(); ++i) {
    const cv::Rect& a = s->components[small[i]].box;
    for (std::size_t j = i + 1; j < small.size(); ++j) {
      const cv::Rect& b = s->components[small[j]].box;
      if (b.x >= a.x + a.width) break;
      // Fragments of one marker nest (a rim around its core) or, when shading across a large
      // marker exceeds the flood range, split it into two overlapping halves whose union is
      // hardly bigger than either; a neighbour only touches.
      const int overlap = (a & b).area();
      const int larger = std::max(a.area(), b.area());
      if (overlap > 0 &&
          (2 * overlap >= std::min(a.area(), b.area()) || 5 * (a | b).area() <= 8 * larger)) {
        parent[Find(parent, static_cast<int>(j))] = Find(parent, static_cast<int>(i));
      }
    }
  }
  std::vector<MarkerBlob> merged(small.size());
  std::vector<bool> used(small.size(), false);
  for (std::size_t i = 0; i < small.size(); ++i) {
    const int root = Find(parent, static_cast<int>(i));
    const Component& c = s->components[small[i]];
    MarkerBlob& m = merged[root];
    m.box = used[root] ? (m.box | c.box) : c.box;
    m.area_px += c.area_px;
    used[root] = true;
  }
  std::vector<MarkerBlob> out;
  for (std::size_t i = 0; i < merged.size(); ++i) {
    if (!used[i]) continue;
    MarkerBlob& m = merged[i];
    const double aspect = static_cast<double>(m.box.width) / m.box.height;
    const double fill = static_cast<double>(m.area_px) / m.box.area();
    if (m.area_px < min_area || m.area_px > max_area) continue;
    if (aspect < options.min_aspect || aspect > options.max_aspect) continue;
    if (fill < options.min_fill) continue;
    m.centre = BoxCentre(m.box);
    out.push_back(m);
  }
  std::sort(out.begin(), out.end(), [](const MarkerBlob& a, const MarkerBlob& b) {
    return a.area_px != b.area_px ? a.area_px > b.area_px : a.box.y < b.box.y;
  });
  return out;
}

bool RefineMarker(const cv::Mat& gray, const cv::Mat& filtered, double core_ratio, int min_height,
                  MarkerBlob* blob) {
  // A thin marker's blob may be only its core: the window spans at least a full marker's
  // height (yaw does not change it), plus a ring of two pixels.
  const int grow = std::max(0, (min_height - blob->box.height + 1) / 2);
  cv::Rect w(blob->box.x - 2, blob->box.y - 2 - grow, blob->box.width + 4,
             blob->box.height + 4 + 2 * grow);
  const cv::Rect image(0, 0, gray.cols, gray.rows);
  // A marker near the image's edge keeps the part of its ring the image shows; one that touches
  // the edge is cut and has no centre to measure.
  const cv::Rect inner(1, 1, gray.cols - 2, gray.rows - 2);
  if ((blob->box & inner) != blob->box) return false;
  w &= image;
  // The blob may be one fragment of its marker (flood fill is relative to the seed): widen the
  // window while its edge still holds marker-dark pixels.
  {
    double darkest_in_box = 255;
    for (int y = blob->box.y; y < blob->box.y + blob->box.height; ++y) {
      for (int x = blob->box.x; x < blob->box.x + blob->box.width; ++x) {
        darkest_in_box = std::min<double>(darkest_in_box, filtered.at<uchar>(y, x));
      }
    }
    std::vector<uchar> edge;
    for (int x = w.x; x < w.x + w.width; ++x) {
      edge.push_back(gray.at<uchar>(w.y, x));
      edge.push_back(gray.at<uchar>(w.y + w.height - 1, x));
    }
    std::nth_element(edge.begin(), edge.begin() + edge.size() / 2, edge.end());
    const double half = 0.5 * (edge[edge.size() / 2] + darkest_in_box);
    auto dark_count = [&](const cv::Rect& r) {
      int n = 0;
      for (int y = r.y; y < r.y + r.height; ++y) {
        for (int x = r.x; x < r.x + r.width; ++x) n += gray.at<uchar>(y, x) < half;
      }
      return n;
    };
    for (int step = 0; step < 3; ++step) {
      bool grown = false;
      if (dark_count({w.x, w.y, 1, w.height}) >= 2) w.x -= 1, w.width += 1, grown = true;
      if (dark_count({w.x + w.width - 1, w.y, 1, w.height}) >= 2) w.width += 1, grown = true;
      if (dark_count({w.x, w.y, w.width, 1}) >= 2) w.y -= 1, w.height += 1, grown = true;
      if (dark_count({w.x, w.y + w.height - 1, w.width, 1}) >= 2) w.height += 1, grown = true;
      w &= image;
      if (!grown) break;
    }
  }
  const double xc = blob->centre.x;
  const double yc = blob->centre.y;
  // The ring of pixels around the blob, fitted by a plane (the surface's shading), twice: the
  // second time without the pixels far off the first fit (another surface, clutter).
  std::vector<cv::Point> ring;
  ring.reserve(2 * (w.width + w.height));
  for (int x = w.x; x < w.x + w.width; ++x) {
    ring.emplace_back(x, w.y);
    ring.emplace_back(x, w.y + w.height - 1);
  }
  for (int y = w.y + 1; y < w.y + w.height - 1; ++y) {
    ring.emplace_back(w.x, y);
    ring.emplace_back(w.x + w.width - 1, y);
  }
  using Vec6 = cv::Vec<double, 6>;
  Vec6 plane(0, 0, 0, 0, 0, 0);
  const double scale = 1.0 / std::max(w.width, w.height);
  auto basis = [&](double x, double y) {
    const double u = (x - xc) * scale, v = (y - yc) * scale;
    return Vec6(1, u, v, u * u, u * v, v * v);
  };
  auto level = [&](double x, double y) { return plane.dot(basis(x, y)); };
  double threshold = 1e9;
  for (int pass = 0; pass < 2; ++pass) {
    cv::Matx<double, 6, 6> a = cv::Matx<double, 6, 6>::zeros();
    Vec6 b(0, 0, 0, 0, 0, 0);
    int used = 0;
    for (const cv::Point& p : ring) {
      const double v = gray.at<uchar>(p);
      if (pass > 0 && std::abs(v - level(p.x, p.y)) > threshold) continue;
      const Vec6 f = basis(p.x, p.y);
      a += f * f.t();
      b += f * v;
      ++used;
    }
    if (used < 6) return false;
    Vec6 solved;
    if (!cv::solve(a, b, solved, cv::DECOMP_SVD)) return false;
    plane = solved;
    std::vector<double> residuals;
    residuals.reserve(ring.size());
    for (const cv::Point& p : ring)
      residuals.push_back(std::abs(gray.at<uchar>(p) - level(p.x, p.y)));
    std::nth_element(residuals.begin(), residuals.begin() + residuals.size() / 2, residuals.end());
    threshold = std::max(4.0, 3 * 1.4826 * residuals[residuals.size() / 2]);
  }
  // Columns beside the blob whose top and bottom ring pixels are both off the fit lie beyond
  // the lower part's silhouette (it is upright): they are background, not marker.
  std::vector<char> skip(w.width, 0);
  for (int x = w.x; x < w.x + w.width; ++x) {
    if (x >= blob->box.x && x < blob->box.x + blob->box.width) continue;
    const double top = gray.at<uchar>(w.y, x) - level(x, w.y);
    const double bottom = gray.at<uchar>(w.y + w.height - 1, x) - level(x, w.y + w.height - 1);
    skip[x - w.x] = std::abs(top) > threshold && std::abs(bottom) > threshold;
  }
  double darkest = 255;
  for (int y = blob->box.y; y < blob->box.y + blob->box.height; ++y) {
    const uchar* row = filtered.ptr<uchar>(y);
    for (int x = blob->box.x; x < blob->box.x + blob->box.width; ++x)
      darkest = std::min<double>(darkest, row[x]);
  }
  const double surround = level(xc, yc);
  const double core = core_ratio > 0 ? core_ratio * surround : darkest;
  if (surround - core < 10) return false;
  // A clipped (overexposed) surround hides the rim's partial coverage: then every pixel darker
  // than half-way counts whole, which clipping biases far less.
  int clipped = 0;
  for (const cv::Point& p : ring) clipped += gray.at<uchar>(p) >= 254;
  const bool binary = clipped * 5 > static_cast<int>(ring.size());
  double sum = 0, sx = 0, sy = 0;
  for (int y = w.y; y < w.y + w.height; ++y) {
    const uchar* row = gray.ptr<uchar>(y);
    for (int x = w.x; x < w.x + w.width; ++x) {
      if (skip[x - w.x]) continue;
      const double s = level(x, y);
      const double m = core_ratio > 0 ? core_ratio * s : core;
      const double c = binary ? (row[x] < 0.5 * (s + m) ? 1.0 : 0.0)
                              : std::clamp((s - row[x]) / std::max(1.0, s - m), 0.0, 1.0);
      sum += c;
      sx += c * x;
      sy += c * y;
    }
  }
  if (sum < 1) return false;
  blob->centre = {sx / sum, sy / sum};
  blob->coverage_px = sum;
  blob->surround = surround;
  // The marker's own level: the median image around the centre.
  const cv::Point c(cvRound(blob->centre.x), cvRound(blob->centre.y));
  double core_sum = 0;
  int core_n = 0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const cv::Point p(c.x + dx, c.y + dy);
      if (!blob->box.contains(p)) continue;
      core_sum += filtered.at<uchar>(p);
      ++core_n;
    }
  }
  blob->core = core_n ? core_sum / core_n : darkest;
  blob->refined = true;
  return true;
}

namespace {

MarkerTriple Ordered(const MarkerBlob& upper, const MarkerBlob& a, const MarkerBlob& b) {
  MarkerTriple t;
  t.upper = upper;
  t.left = a.centre.x <= b.centre.x ? a : b;
  t.right = a.centre.x <= b.centre.x ? b : a;
  return t;
}

}  // namespace

bool ThreeLargest(const std::vector<MarkerBlob>& blobs, MarkerTriple* out) {
  if (blobs.size() < 3) return false;
  int top = 0;
  for (int i = 1; i < 3; ++i) {
    if (blobs[i].centre.y < blobs[top].centre.y) top = i;
  }
  const int a = top == 0 ? 1 : 0;
  const int b = top == 2 ? 1 : 2;
  *out = Ordered(blobs[top], blobs[a], blobs[b]);
  return true;
}

SurfaceStretch SampleStretch(const cv::Mat& filtered, cv::Point2d a, cv::Point2d b) {
  constexpr int kSamples = 16;
  double values[kSamples];
  double ts[kSamples];
  int n = 0;
  for (int i = 0; i < kSamples; ++i) {
    const double t = 0.2 + 0.6 * i / (kSamples - 1);
    const cv::Point p(cvRound(a.x + t * (b.x - a.x)), cvRound(a.y + t * (b.y - a.y)));
    if (p.x < 0 || p.y < 0 || p.x >= filtered.cols || p.y >= filtered.rows) continue;
    ts[n] = t;
    values[n++] = filtered.at<uchar>(p);
  }
  SurfaceStretch out;
  if (n < kSamples / 2) return out;
  // Shading makes a smooth ramp; a silhouette crossed makes a step. Fit the ramp, count the
  // samples off it.
  double st = 0, sv = 0, stt = 0, stv = 0;
  for (int i = 0; i < n; ++i) {
    st += ts[i];
    sv += values[i];
    stt += ts[i] * ts[i];
    stv += ts[i] * values[i];
  }
  const double det = n * stt - st * st;
  const double slope = det > 1e-12 ? (n * stv - st * sv) / det : 0;
  const double offset = (sv - slope * st) / n;
  out.level = sv / n;
  int off = 0;
  for (int i = 0; i < n; ++i) {
    off += std::abs(values[i] - (offset + slope * ts[i])) > 0.15 * out.level + 4;
  }
  out.uneven = static_cast<double>(off) / n;
  return out;
}

namespace {

// The point just outside `blob`'s box from its centre towards `direction`.
cv::Point2d Beyond(const MarkerBlob& blob, cv::Point2d direction) {
  const double len = std::hypot(direction.x, direction.y);
  if (!(len > 0)) return blob.centre;
  const cv::Point2d u = direction / len;
  const double reach =
      std::min(std::abs(u.x) > 1e-9 ? (0.5 * blob.box.width + 1) / std::abs(u.x) : 1e9,
               std::abs(u.y) > 1e-9 ? (0.5 * blob.box.height + 1) / std::abs(u.y) : 1e9);
  return blob.centre + u * std::min(reach, 0.45 * len);
}

}  // namespace

std::vector<MarkerTriple> RankReferenceTriples(const std::vector<MarkerBlob>& blobs,
                                               const cv::Mat& filtered, int limit) {
  const int count = std::min<int>(static_cast<int>(blobs.size()), 16);
  std::vector<std::pair<double, MarkerTriple>> ranked;
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < count; ++j) {
      const MarkerBlob& a = blobs[i];
      const MarkerBlob& b = blobs[j];
      const double n = b.centre.x - a.centre.x;
      if (i == j || n < 4) continue;
      const double dy = std::abs(a.centre.y - b.centre.y);
      if (dy > 0.15 * n + 2) continue;
      const cv::Point2d mid = (a.centre + b.centre) * 0.5;
      const double size_diff = std::abs(a.area_px - b.area_px) / double(a.area_px + b.area_px);
      for (int k = 0; k < count; ++k) {
        if (k == i || k == j) continue;
        const MarkerBlob& c = blobs[k];
        if (c.centre.y > mid.y - 0.3 * n) continue;
        const double off = std::abs(c.centre.x - mid.x);
        if (off > 0.2 * n + 2) continue;
        // The stretches between the blobs, the blobs themselves left out (large markers close
        // together leave little between them).
        const SurfaceStretch pair =
            SampleStretch(filtered, Beyond(a, b.centre - a.centre), Beyond(b, a.centre - b.centre));
        const SurfaceStretch up = SampleStretch(filtered, mid, Beyond(c, mid - c.centre));
        if (pair.uneven > 0.25 || up.uneven > 0.25) continue;
        const double score = off / n + dy / n + 0.5 * size_diff + pair.uneven + up.uneven;
        ranked.emplace_back(score, Ordered(c, a, b));
      }
    }
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<MarkerTriple> out;
  for (const auto& [score, t] : ranked) {
    if (static_cast<int>(out.size()) >= limit) break;
    out.push_back(t);
  }
  return out;
}

bool ChooseReferenceTriple(const std::vector<MarkerBlob>& blobs, const cv::Mat& filtered,
                           bool thesis_mode, MarkerTriple* out) {
  if (thesis_mode) return ThreeLargest(blobs, out);
  const std::vector<MarkerTriple> ranked = RankReferenceTriples(blobs, filtered, 1);
  if (ranked.empty()) return false;
  *out = ranked[0];
  return true;
}

MarkerAngles ComputeThesisAngles(const MarkerTriple& t, const MarkerReference& ref) {
  MarkerAngles out;
  const double n = t.right.centre.x - t.left.centre.x;
  const double yaw = std::acos(std::clamp(n / ref.n_px, 0.0, 1.0));  // eq. 4-1
  out.yaw_deg = DegFromRad(yaw);
  const cv::Point2d mid = (t.left.centre + t.right.centre) * 0.5;
  out.pivot_px = {mid.x, mid.y - ref.e_px};
  const double dx = t.upper.centre.x - mid.x;
  const double cos_yaw = std::max(1e-3, std::cos(yaw));
  // Eqs. 4-2..4-5: the upper marker's offset from the pivot; the horizontal part shrinks by
  // cos(yaw) (a = e / cos(yaw) in the thesis).
  out.bend_deg = DegFromRad(std::atan2(-dx / cos_yaw, out.pivot_px.y - t.upper.centre.y));
  return out;
}

}  // namespace armmimic::internal
