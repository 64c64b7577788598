#include "common/arm_appearance.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "armmimic/core/angles.h"
#include "common/light_gain.h"
#include "common/order_statistic.h"
#include "common/pixel_rows.h"

namespace armmimic::arm {
namespace {

constexpr int kLevels = 16;  // colour levels a channel in the histograms
constexpr int kBins = kLevels * kLevels * kLevels;
// Prior odds of a changed pixel in the arm's reach being something else than the arm (a shadow,
// the head that moved) in a colour of the surroundings.
constexpr float kOtherOdds = 0.25f;
// Floor of each normalised histogram: a colour neither histogram has shown gets
// kArmFloor / (kArmFloor + kOtherOdds * kAroundFloor) = 1/3.
constexpr float kArmFloor = 1e-4f, kAroundFloor = 8e-4f;
// A pixel the arm hid since the start (no background learnt yet) counts with this share of its
// colour's probability.
constexpr float kUnknownShare = 0.6f;
// Change (distance from the background's neighbourhood, grey levels) below which a pixel is
// explained by the background, at least; and how much more counts as a full difference.
constexpr double kMinChange = 6, kMinChangeSpan = 12;
constexpr double kChangeQuantile = 0.9;  // of the background pixels' distances: their noise
// The background's guard (LearntBackground::Update): the least share of the rate at which a
// pixel that looks like the arm still follows, and how many updates a changed or unknown pixel
// in the arm's colour must hold one colour before it is the scene.
constexpr double kMinFollowShare = 0.05;
constexpr int kSettleFrames = 20;
constexpr float kArmColour = 0.5f;  // P(arm | colour) from which a colour is the arm's

// [1 2 1] smoothing along one axis of a kLevels^3 histogram (stride 1, kLevels or kLevels^2).
void SmoothAxis(std::vector<float>& h, int stride) {
  std::vector<float> out(h.size());
  for (int i = 0; i < kBins; ++i) {
    const int k = (i / stride) % kLevels;
    const float left = k > 0 ? h[i - stride] : h[i];
    const float right = k < kLevels - 1 ? h[i + stride] : h[i];
    out[i] = 0.25f * left + 0.5f * h[i] + 0.25f * right;
  }
  h.swap(out);
}

// Half-widths, hand: bounds as shares of the arm's length, and where they are read.
constexpr double kMinHalfWidth = 1.5, kMaxHalfWidthShare = 0.12;
constexpr double kWidthFrom = 0.25, kWidthTo = 0.8;
constexpr double kTypicalHalfWidthShare = 0.06;  // of the arm's length: a human upper arm
constexpr double kForeToUpperWidth = 0.85;
constexpr int kWidthSamples = 9;
constexpr double kHandStartShare = 0.2;  // of the forearm: surely the hand, beyond the wrist
constexpr double kMinHandShare = 0.25, kMaxHandShare = 0.6;
constexpr double kAroundShare = 1.3;  // the surroundings reach this far (times the arm's reach)

bool IsArm(const cv::Mat& bgr, const ColourModel& colour, const cv::Point2d& p) {
  const int x = cvRound(p.x), y = cvRound(p.y);
  if (x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows) return false;
  return colour.Probability(bgr.at<cv::Vec3b>(y, x)) >= 0.5f;
}

// How far the arm's colour runs from `p` along `dir`, in half-pixel steps, up to `max_px`.
double Run(const cv::Mat& bgr, const ColourModel& colour, const cv::Point2d& p,
           const cv::Point2d& dir, double max_px) {
  for (double d = 0.5; d <= max_px; d += 0.5) {
    if (!IsArm(bgr, colour, p + d * dir)) return d - 0.25;
  }
  return max_px;
}

// Half the width of the segment from `a` to `b`: the median over samples of the two-sided width
// where the colour ends on both sides, else of the narrower side; -1 when the colour runs on
// beyond `max_hw` on both sides (the segment lies on something of its own colour).
double HalfWidth(const cv::Mat& bgr, const ColourModel& colour, const cv::Point2d& a,
                 const cv::Point2d& b, double max_hw) {
  const cv::Point2d ab = b - a;
  const double len = std::sqrt(ab.dot(ab));
  if (!(len > 0)) return kMinHalfWidth;
  const cv::Point2d u = ab / len, n(-u.y, u.x);
  std::vector<double> both, one;
  for (int k = 0; k < kWidthSamples; ++k) {
    const cv::Point2d p = a + (kWidthFrom + (kWidthTo - kWidthFrom) * k / (kWidthSamples - 1)) * ab;
    if (!IsArm(bgr, colour, p)) continue;
    const double l = Run(bgr, colour, p, n, max_hw), r = Run(bgr, colour, p, -n, max_hw);
    if (l < max_hw && r < max_hw) both.push_back(0.5 * (l + r));
    if (l < max_hw || r < max_hw) one.push_back(std::min(l, r));
  }
  std::vector<double>& v = both.size() * 2 >= one.size() && !both.empty() ? both : one;
  if (v.size() * 3 < kWidthSamples) return -1;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return std::clamp(v[v.size() / 2], kMinHalfWidth, max_hw);
}

}  // namespace

LearntArm LearnArm(const cv::Mat& bgr, const ArmJoints& joints, double reach_px) {
  LearntArm out;
  ArmShape& s = out.shape;
  s.upper_px = cv::norm(joints.elbow - joints.shoulder);
  s.fore_px = cv::norm(joints.wrist - joints.elbow);
  const double arm_px = s.upper_px + s.fore_px;
  const double max_hw = std::max(2.0, kMaxHalfWidthShare * arm_px);
  cv::Mat around = cv::Mat::zeros(bgr.size(), CV_8U);
  cv::circle(around, cv::Point(cvRound(joints.shoulder.x), cvRound(joints.shoulder.y)),
             cvRound(kAroundShare * reach_px), cv::Scalar(255), cv::FILLED);
  // First the colour along the axes (surely the arm) against everything around a generous band.
  ArmShape axis = s;
  axis.upper_hw = axis.fore_hw = 0;
  axis.hand_px = kHandStartShare * s.fore_px;
  ArmShape band = s;
  band.upper_hw = band.fore_hw = max_hw + 2;
  band.hand_px = kMaxHandShare * s.fore_px + max_hw;
  cv::Mat axis_mask = cv::Mat::zeros(bgr.size(), CV_8U), band_mask = axis_mask.clone();
  DrawArm(axis_mask, joints, axis, 0);
  DrawArm(band_mask, joints, band, 0);
  cv::Mat outside = around.clone();
  outside.setTo(0, band_mask);
  ColourModel first;
  first.Learn(bgr, axis_mask, outside);
  s.upper_hw = HalfWidth(bgr, first, joints.shoulder, joints.elbow, max_hw);
  s.fore_hw = HalfWidth(bgr, first, joints.elbow, joints.wrist, max_hw);
  // A segment whose width could not be read takes the other's (a forearm is a little thinner),
  // or a share of the arm's length typical of a human arm.
  if (s.upper_hw < 0 && s.fore_hw < 0) {
    s.upper_hw = std::max(kMinHalfWidth, kTypicalHalfWidthShare * arm_px);
    s.fore_hw = kForeToUpperWidth * s.upper_hw;
  } else if (s.upper_hw < 0) {
    s.upper_hw = std::min(max_hw, s.fore_hw / kForeToUpperWidth);
  } else if (s.fore_hw < 0) {
    s.fore_hw = std::max(kMinHalfWidth, kForeToUpperWidth * s.upper_hw);
  }
  if (s.fore_px > 0) {
    const cv::Point2d u = (joints.wrist - joints.elbow) / s.fore_px;
    const double hand = Run(bgr, first, joints.wrist, u, kMaxHandShare * s.fore_px);
    s.hand_px = std::max(kMinHandShare * s.fore_px, hand);
  }
  // Then the whole arm against its surroundings.
  out.mask = cv::Mat::zeros(bgr.size(), CV_8U);
  DrawArm(out.mask, joints, s, -0.5);
  cv::Mat clear = cv::Mat::zeros(bgr.size(), CV_8U);
  DrawArm(clear, joints, s, 2);
  around.setTo(0, clear);
  out.colour.Learn(bgr, out.mask, around);
  return out;
}

void DrawArm(cv::Mat& mask, const ArmJoints& joints, const ArmShape& shape, double grow_px,
             int value) {
  auto pt = [](const cv::Point2d& p) { return cv::Point(cvRound(p.x), cvRound(p.y)); };
  auto thick = [&](double hw) { return std::max(1, cvRound(2 * (hw + grow_px) + 1)); };
  cv::line(mask, pt(joints.shoulder), pt(joints.elbow), cv::Scalar(value), thick(shape.upper_hw));
  cv::line(mask, pt(joints.elbow), pt(joints.wrist), cv::Scalar(value), thick(shape.fore_hw));
  const double fl = cv::norm(joints.wrist - joints.elbow);
  if (shape.hand_px > 0 && fl > 0) {
    const cv::Point2d hand = joints.wrist + shape.hand_px / fl * (joints.wrist - joints.elbow);
    cv::line(mask, pt(joints.wrist), pt(hand), cv::Scalar(value), thick(shape.fore_hw));
  }
}

std::vector<float> ColourModel::Histogram(const cv::Mat& bgr, const cv::Mat& mask) {
  std::vector<float> h(kBins, 0.f);
  double n = 0;
  for (int y = 0; y < bgr.rows; ++y) {
    const cv::Vec3b* row = bgr.ptr<cv::Vec3b>(y);
    const uchar* m = mask.ptr<uchar>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      if (!m[x]) continue;
      h[Index(row[x])] += 1.f;
      ++n;
    }
  }
  if (n > 0) {
    for (float& v : h) v = static_cast<float>(v / n);
  }
  SmoothAxis(h, 1);
  SmoothAxis(h, kLevels);
  SmoothAxis(h, kLevels * kLevels);
  return h;
}

void ColourModel::Learn(const cv::Mat& bgr, const cv::Mat& arm, const cv::Mat& around) {
  arm_ = Histogram(bgr, arm);
  around_ = Histogram(bgr, around);
  Rebuild();
}

void ColourModel::Adapt(const cv::Mat& bgr, const cv::Mat& arm, double rate) {
  if (arm_.empty()) return;
  const std::vector<float> now = Histogram(bgr, arm);
  const float r = static_cast<float>(rate);
  for (int i = 0; i < kBins; ++i) arm_[i] = (1 - r) * arm_[i] + r * now[i];
  Rebuild();
}

void ColourModel::Rebuild() {
  prob_.resize(kBins);
  for (int i = 0; i < kBins; ++i) {
    const float a = arm_[i] + kArmFloor, s = around_[i] + kAroundFloor;
    prob_[i] = a / (a + kOtherOdds * s);
  }
}

void LearntBackground::Reset(const cv::Mat& bgr, const cv::Mat& hidden) {
  bgr.convertTo(image_, CV_32FC3);
  cv::compare(hidden, 0, known_, cv::CMP_EQ);
  pending_ = cv::Mat::zeros(bgr.size(), CV_32FC3);
  settled_ = cv::Mat::zeros(bgr.size(), CV_8U);
}

void LearntBackground::Update(const cv::Mat& bgr, const cv::Mat& hidden, double rate,
                              const cv::Rect& region, const EvidenceMap& evidence,
                              const ColourModel& colour) {
  const cv::Rect r = region & cv::Rect(0, 0, bgr.cols, bgr.rows);
  const cv::Rect er = evidence.region();
  const cv::Mat& map = evidence.map();
  const float tolerance2 =
      static_cast<float>(evidence.change_threshold() * evidence.change_threshold());
  for (int y = r.y; y < r.y + r.height; ++y) {
    const cv::Vec3b* in = bgr.ptr<cv::Vec3b>(y);
    const uchar* h = hidden.ptr<uchar>(y);
    cv::Vec3f* b = image_.ptr<cv::Vec3f>(y);
    uchar* k = known_.ptr<uchar>(y);
    cv::Vec3f* pend = pending_.ptr<cv::Vec3f>(y);
    uchar* held = settled_.ptr<uchar>(y);
    const bool row_in = y >= er.y && y < er.y + er.height && !map.empty();
    const float* e = row_in ? map.ptr<float>(y - er.y) : nullptr;
    for (int x = r.x; x < r.x + r.width; ++x) {
      uchar& n = held[x];
      if (h[x]) {
        n = 0;
        continue;
      }
      const cv::Vec3f c(in[x][0], in[x][1], in[x][2]);
      const cv::Vec3f diff = c - b[x];
      const bool explained = k[x] && diff.dot(diff) <= tolerance2;
      if (!explained && colour.valid() && colour.Probability(in[x]) >= kArmColour) {
        // Changed, or never seen, in the arm's colour: the scene once it has held one colour.
        const cv::Vec3f d = c - pend[x];
        if (n > 0 && d.dot(d) <= tolerance2) {
          pend[x] += (1.0f / (n + 1)) * d;
          if (n < 255) ++n;
        } else {
          pend[x] = c;
          n = 1;
        }
        if (n >= kSettleFrames) {
          b[x] = pend[x];
          k[x] = 255;
        }
      } else if (k[x]) {
        // Explained: followed as much as it does not look like the arm; changed in another
        // colour (a shadow, the light): followed.
        double a = rate;
        if (explained && e && x >= er.x && x < er.x + er.width) {
          a = rate * std::max(kMinFollowShare, 1.0 - e[x - er.x]);
        }
        b[x] += static_cast<float>(a) * diff;
        n = 0;
      } else {
        b[x] = c;  // never seen, in another colour: the scene as it is
        k[x] = 255;
      }
    }
  }
}

namespace {

// max(kMinChange, the kChangeQuantile quantile of `sampled` distances) from the distances above
// kMinChange alone (`above`, reordered): the others cannot move it.
double ChangeNoise(std::vector<float>* above, std::size_t sampled) {
  if (sampled == 0) return kMinChange;
  const auto at = static_cast<std::size_t>(kChangeQuantile * (sampled - 1));
  const std::size_t at_most_min = sampled - above->size();
  if (at < at_most_min) return kMinChange;
  return std::max(kMinChange,
                  static_cast<double>(KthSmallest(above->data(), above->size(), at - at_most_min)));
}

}  // namespace

void EvidenceMap::Compute(const cv::Mat& bgr, const LearntBackground& background,
                          const ColourModel& colour, const cv::Rect& region,
                          const cv::Mat& ignore) {
  region_ = region & cv::Rect(0, 0, bgr.cols, bgr.rows);
  map_.create(region_.size(), CV_32F);
  cols_m1_ = region_.width - 1;
  rows_m1_ = region_.height - 1;
  if (region_.empty()) return;
  // The frame in the background's light, inside the region.
  const cv::Mat gain = LightGain(bgr, background.image(), background.known(), ignore, region_);
  relit_.create(region_.size(), CV_8UC3);
  for (int y = 0; y < region_.height; ++y) {
    const cv::Vec3b* in = bgr.ptr<cv::Vec3b>(y + region_.y) + region_.x;
    cv::Vec3b* px = relit_.ptr<cv::Vec3b>(y);
    const cv::Vec3f* g = gain.ptr<cv::Vec3f>(y);
    DivideRow(in[0].val, g[0].val, px[0].val, 3 * region_.width);
  }
  const cv::Mat b = background.image()(region_);
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
  cv::erode(b, low_, kernel);
  cv::dilate(b, high_, kernel);
  // The distance of every pixel from its background neighbourhood; the background pixels' own
  // distances (away from the arm) set how much change is noise in this frame.
  dist_.create(region_.size(), CV_32F);
  cv::Mat& dist = dist_;
  // The noise below is max(kMinChange, a quantile of the sampled distances): only the distances
  // above kMinChange can move it, so only they are kept, and the rest counted.
  distances_.clear();
  squares_.resize(static_cast<std::size_t>(3 * region_.width));
  std::size_t sampled = 0;
  for (int y = 0; y < region_.height; ++y) {
    const cv::Vec3b* in = relit_.ptr<cv::Vec3b>(y);
    const cv::Vec3f* lo = low_.ptr<cv::Vec3f>(y);
    const cv::Vec3f* hi = high_.ptr<cv::Vec3f>(y);
    const uchar* known = background.known().ptr<uchar>(y + region_.y) + region_.x;
    const uchar* ign = ignore.empty() ? nullptr : ignore.ptr<uchar>(y + region_.y) + region_.x;
    float* d = dist.ptr<float>(y);
    // Each channel's squared distance from its background neighbourhood, the row at once.
    float* sq = squares_.data();
    SquaredOutsideRow(in[0].val, lo[0].val, hi[0].val, sq, 3 * region_.width);
    for (int x = 0; x < region_.width; ++x) {
      if (!known[x]) {
        d[x] = -1;
        continue;
      }
      d[x] = std::sqrt(sq[3 * x] + sq[3 * x + 1] + sq[3 * x + 2]);
      if ((x & 1) == 0 && (y & 1) == 0 && !(ign && ign[x])) {
        ++sampled;
        if (d[x] > kMinChange) distances_.push_back(d[x]);
      }
    }
  }
  const double low = ChangeNoise(&distances_, sampled);
  const double span = std::max(kMinChangeSpan, low);
  full_change_ = low + span;
  const float lowf = static_cast<float>(low), inv = static_cast<float>(1 / span);
  const std::vector<float>& table = colour.table();
  for (int y = 0; y < region_.height; ++y) {
    const cv::Vec3b* in = relit_.ptr<cv::Vec3b>(y);
    const float* d = dist.ptr<float>(y);
    float* out = map_.ptr<float>(y);
    for (int x = 0; x < region_.width; ++x) out[x] = table[ColourModel::Index(in[x])];
    EvidenceRow(d, out, region_.width, lowf, inv, kUnknownShare);
  }
}

}  // namespace armmimic::arm
