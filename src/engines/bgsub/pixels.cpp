#include "bgsub/pixels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "common/order_statistic.h"

namespace armmimic::bgsub {
namespace {

// A pixel differs when a channel is off by more than kNoiseFactor times its noise plus
// kQuantisation grey levels (compression's blocks and rounding, which the noise of a still
// scene does not show), and never for less than kMinThreshold.
constexpr double kNoiseFactor = 4.0;
constexpr double kQuantisation = 4.0;
constexpr double kMinThreshold = 8.0;
// The gain's samples: a grid of this step, skipping dark and saturated levels.
constexpr int kGainStep = 4;
constexpr int kGainMinLevel = 24;
constexpr int kGainMaxLevel = 250;
// Gain blocks of about this many pixels a side (a soft shadow is several blocks wide). A block's
// gain stands when enough of its samples agree with its median (within kAgree); one off its
// neighbours' median by more than kOutlier is a block the arm covers, and takes theirs.
constexpr int kBlockPx = 40;
constexpr double kAgree = 0.06;
constexpr double kMinAgreeing = 0.4;
constexpr double kOutlier = 0.08;

// A shadow: the reference darkened by one factor in every channel (the colour kept) and its
// texture kept. Only where the reference shows texture (a patch's spread at least kTextureNoise
// times the noise) can a darker pixel be told from an arm of the room's colour, which hides the
// texture; on a plain wall nothing is called a shadow.
constexpr double kShadowMin = 0.3, kShadowMax = 0.92;  // the darkening factor
constexpr double kShadowChroma = 0.08;  // channels' factors within this of their mean
constexpr int kShadowPatch = 7;         // the texture's patch, pixels a side
constexpr double kTextureNoise = 2.0;
constexpr double kTextureKept = 0.7;  // correlation of the patch with the reference's
// Below this the texture is lost (in between: a patch across the shadow's own edge).
constexpr double kTextureLost = 0.3;
// A region of candidates is a shadow where this share of its textured pixels keep the texture,
// and at least kMinKeptPixels do.
constexpr double kShadowRegionShare = 0.75;
constexpr int kMinKeptPixels = 10;

float Median(std::vector<float>* v) {
  if (v->empty()) return 1.0f;
  return arm::KthSmallest(v->data(), v->size(), v->size() / 2);
}

// One gain per channel of `bgr` over `reference`: the median ratio over a sparse grid.
cv::Scalar GlobalGain(const cv::Mat& bgr, const cv::Mat& reference) {
  std::array<std::vector<float>, 3> ratios;
  for (int y = kGainStep / 2; y < bgr.rows; y += kGainStep) {
    const cv::Vec3b* f = bgr.ptr<cv::Vec3b>(y);
    const cv::Vec3b* b = reference.ptr<cv::Vec3b>(y);
    for (int x = kGainStep / 2; x < bgr.cols; x += kGainStep) {
      for (int c = 0; c < 3; ++c) {
        if (b[x][c] < kGainMinLevel || b[x][c] > kGainMaxLevel || f[x][c] > kGainMaxLevel) continue;
        ratios[static_cast<std::size_t>(c)].push_back(static_cast<float>(f[x][c]) / b[x][c]);
      }
    }
  }
  cv::Scalar g(1, 1, 1);
  for (int c = 0; c < 3; ++c) {
    if (ratios[static_cast<std::size_t>(c)].size() >= 16) {
      g[c] = Median(&ratios[static_cast<std::size_t>(c)]);
    }
  }
  return g;
}

// 255 where a channel of |bgr - reference| exceeds `threshold` (CV_8UC3 each).
void Exceeds(const cv::Mat& bgr, const cv::Mat& reference, const cv::Mat& threshold, cv::Mat* diff,
             cv::Mat* any, cv::Mat* mask) {
  cv::absdiff(bgr, reference, *diff);
  cv::compare(*diff, threshold, *diff, cv::CMP_GT);
  // Any channel over: every grey weight is positive.
  cv::cvtColor(*diff, *any, cv::COLOR_BGR2GRAY);
  cv::threshold(*any, *mask, 0, 255, cv::THRESH_BINARY);
}

// Clears from `mask` (CV_8UC1 of `frame`'s size) the pixels of `frame` that are `reference`
// (CV_8UC3, the same size) in shadow. `noise` in grey levels. A pixel darkened by one factor with
// its colour kept is a candidate; where the reference shows texture, the patch says whether the
// texture is kept (the room in shadow) or lost (something in front of it). A connected region of
// candidates whose textured pixels mostly keep it is a shadow as a whole, its plain pixels too
// (a shadow on dots or bricks also falls between them).
void ClearShadows(const cv::Mat& frame, const cv::Mat& reference, double noise, cv::Mat* mask) {
  if (cv::countNonZero(*mask) == 0) return;
  cv::Mat f, r;
  cv::cvtColor(frame, f, cv::COLOR_BGR2GRAY);
  cv::cvtColor(reference, r, cv::COLOR_BGR2GRAY);
  f.convertTo(f, CV_32F);
  r.convertTo(r, CV_32F);
  const cv::Size k(kShadowPatch, kShadowPatch);
  cv::Mat mf, mr, mff, mrr, mfr;
  cv::boxFilter(f, mf, CV_32F, k);
  cv::boxFilter(r, mr, CV_32F, k);
  cv::boxFilter(f.mul(f), mff, CV_32F, k);
  cv::boxFilter(r.mul(r), mrr, CV_32F, k);
  cv::boxFilter(f.mul(r), mfr, CV_32F, k);
  const double min_var = kTextureNoise * kTextureNoise * std::max(1.0, noise * noise);
  // What each pixel of the mask is: no candidate; a candidate on plain reference; a candidate
  // whose patch keeps the reference's texture; one whose patch loses it.
  enum : uchar { kNoCandidate = 0, kPlain, kTextureKeptHere, kTextureLostHere };
  cv::Mat kind = cv::Mat::zeros(frame.size(), CV_8U);
  for (int y = 0; y < frame.rows; ++y) {
    const uchar* m = mask->ptr<uchar>(y);
    uchar* kd = kind.ptr<uchar>(y);
    const cv::Vec3b* fp = frame.ptr<cv::Vec3b>(y);
    const cv::Vec3b* rp = reference.ptr<cv::Vec3b>(y);
    for (int x = 0; x < frame.cols; ++x) {
      if (!m[x]) continue;
      double ratio[3], mean = 0;
      for (int c = 0; c < 3; ++c) {
        ratio[c] = (fp[x][c] + 1.0) / (rp[x][c] + 1.0);
        mean += ratio[c] / 3;
      }
      if (mean < kShadowMin || mean > kShadowMax) continue;
      bool same_colour = true;
      for (int c = 0; c < 3; ++c) {
        same_colour &= std::fabs(ratio[c] - mean) <= kShadowChroma * mean;
      }
      if (!same_colour) continue;
      kd[x] = kPlain;
      const double vr = mrr.at<float>(y, x) - mr.at<float>(y, x) * mr.at<float>(y, x);
      const double vf = mff.at<float>(y, x) - mf.at<float>(y, x) * mf.at<float>(y, x);
      if (vr < min_var) continue;
      const double cov = mfr.at<float>(y, x) - mf.at<float>(y, x) * mr.at<float>(y, x);
      const double ncc = vf > 0 ? cov / std::sqrt(vr * vf) : 0;
      if (ncc >= kTextureKept) kd[x] = kTextureKeptHere;
      if (ncc < kTextureLost) kd[x] = kTextureLostHere;
    }
  }
  cv::Mat labels;
  const int n = cv::connectedComponents(kind != kNoCandidate, labels, 8, CV_32S);
  std::vector<int> kept(static_cast<std::size_t>(n), 0), lost(static_cast<std::size_t>(n), 0);
  for (int y = 0; y < frame.rows; ++y) {
    const uchar* kd = kind.ptr<uchar>(y);
    const int* l = labels.ptr<int>(y);
    for (int x = 0; x < frame.cols; ++x) {
      if (kd[x] == kTextureKeptHere) ++kept[static_cast<std::size_t>(l[x])];
      if (kd[x] == kTextureLostHere) ++lost[static_cast<std::size_t>(l[x])];
    }
  }
  for (int y = 0; y < frame.rows; ++y) {
    uchar* m = mask->ptr<uchar>(y);
    const uchar* kd = kind.ptr<uchar>(y);
    const int* l = labels.ptr<int>(y);
    for (int x = 0; x < frame.cols; ++x) {
      if (kd[x] == kNoCandidate || kd[x] == kTextureLostHere) continue;
      const std::size_t c = static_cast<std::size_t>(l[x]);
      if (kd[x] == kTextureKeptHere ||
          (kept[c] >= kMinKeptPixels && kept[c] >= kShadowRegionShare * (kept[c] + lost[c])))
        m[x] = 0;
    }
  }
}

// Blocks without a gain take their valid neighbours' mean (repeatedly), then `fallback`; a block
// far from its neighbours' median takes that median.
void RepairGrid(const std::vector<uchar>& valid_in, const cv::Vec3f& fallback, cv::Mat* grid) {
  const int w = grid->cols, h = grid->rows;
  std::vector<uchar> valid = valid_in;
  for (int pass = 0; pass < w + h; ++pass) {
    std::vector<uchar> next = valid;
    bool missing = false;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (valid[static_cast<std::size_t>(y * w + x)]) continue;
        cv::Vec3f sum(0, 0, 0);
        int n = 0;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int yy = y + dy, xx = x + dx;
            if (yy < 0 || xx < 0 || yy >= h || xx >= w) continue;
            if (!valid[static_cast<std::size_t>(yy * w + xx)]) continue;
            sum += grid->at<cv::Vec3f>(yy, xx);
            ++n;
          }
        }
        if (n > 0) {
          grid->at<cv::Vec3f>(y, x) = sum / n;
          next[static_cast<std::size_t>(y * w + x)] = 1;
        } else {
          missing = true;
        }
      }
    }
    valid = next;
    if (!missing) break;
  }
  for (int i = 0; i < w * h; ++i) {
    if (!valid[static_cast<std::size_t>(i)]) grid->at<cv::Vec3f>(i / w, i % w) = fallback;
  }
  const cv::Mat before = grid->clone();
  std::vector<float> around;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) {
        around.clear();
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int yy = y + dy, xx = x + dx;
            if ((dx || dy) && yy >= 0 && xx >= 0 && yy < h && xx < w) {
              around.push_back(before.at<cv::Vec3f>(yy, xx)[c]);
            }
          }
        }
        const float m = Median(&around);
        float& g = grid->at<cv::Vec3f>(y, x)[c];
        if (std::fabs(g - m) > kOutlier * m) g = m;
      }
    }
  }
}

}  // namespace

void PixelModel::Begin(const cv::Size& size) {
  sum_ = cv::Mat::zeros(size, CV_32FC3);
  sum_sq_ = cv::Mat::zeros(size, CV_32FC3);
  count_ = 0;
  threshold_.release();
  blocks_ = cv::Size(std::max(1, (size.width + kBlockPx / 2) / kBlockPx),
                     std::max(1, (size.height + kBlockPx / 2) / kBlockPx));
}

void PixelModel::AddStandstill(const cv::Mat& bgr) {
  cv::accumulate(bgr, sum_);
  cv::accumulateSquare(bgr, sum_sq_);
  ++count_;
}

void PixelModel::Finish(const cv::Mat& background, int cap) {
  background_ = background.clone();
  const double n = std::max(1, count_);
  cv::Mat mean, var;
  sum_.convertTo(mean, CV_32FC3, 1.0 / n);
  mean.convertTo(standstill_, CV_8UC3);
  var = sum_sq_ / n - mean.mul(mean);
  std::vector<cv::Mat> ch;
  cv::split(var, ch);
  cv::Mat sigma = cv::max(cv::max(ch[0], ch[1]), ch[2]);
  cv::max(sigma, 0, sigma);
  cv::sqrt(sigma, sigma);
  std::vector<float> samples;
  for (int y = 1; y < sigma.rows; y += 3) {
    const float* s = sigma.ptr<float>(y);
    for (int x = 1; x < sigma.cols; x += 3) samples.push_back(s[x]);
  }
  noise_ = samples.empty() ? 0.0 : Median(&samples);
  cv::Mat t1;
  cv::max(sigma, noise_, sigma);
  sigma.convertTo(t1, CV_8UC1, kNoiseFactor, kQuantisation);
  cv::max(t1, kMinThreshold, t1);
  cv::min(t1, std::max(cap, static_cast<int>(kMinThreshold)), t1);
  cv::merge(std::vector<cv::Mat>{t1, t1, t1}, threshold_);
  standstill_gain_ = GlobalGain(standstill_, background_);
  standstill_.convertTo(standstill_f_, CV_32FC3);
  background_.convertTo(background_f_, CV_32FC3);
  cv::multiply(background_f_, standstill_gain_, background_f_);
  sum_.release();
  sum_sq_.release();
}

void PixelModel::MeasureGain(const cv::Mat& bgr, const cv::Mat& ignore) {
  const int bw = (bgr.cols + blocks_.width - 1) / blocks_.width;
  const int bh = (bgr.rows + blocks_.height - 1) / blocks_.height;
  const int count = blocks_.area();
  thread_local std::vector<std::array<std::vector<float>, 3>> ratios;
  ratios.resize(static_cast<std::size_t>(count));
  for (auto& b : ratios) {
    for (auto& v : b) v.clear();
  }
  for (int y = kGainStep / 2; y < bgr.rows; y += kGainStep) {
    const cv::Vec3b* f = bgr.ptr<cv::Vec3b>(y);
    const cv::Vec3b* s = standstill_.ptr<cv::Vec3b>(y);
    const uchar* skip = ignore.empty() ? nullptr : ignore.ptr<uchar>(y);
    const int row = (y / bh) * blocks_.width;
    for (int x = kGainStep / 2; x < bgr.cols; x += kGainStep) {
      if (skip && skip[x]) continue;
      auto& block = ratios[static_cast<std::size_t>(row + x / bw)];
      for (int c = 0; c < 3; ++c) {
        if (s[x][c] < kGainMinLevel || s[x][c] > kGainMaxLevel || f[x][c] > kGainMaxLevel) continue;
        block[static_cast<std::size_t>(c)].push_back(static_cast<float>(f[x][c]) / s[x][c]);
      }
    }
  }
  gain_.create(blocks_, CV_32FC3);
  std::vector<uchar> valid(static_cast<std::size_t>(count), 1);
  std::array<std::vector<float>, 3> all;
  for (int i = 0; i < count; ++i) {
    for (int c = 0; c < 3; ++c) {
      std::vector<float>& v = ratios[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)];
      const float m = Median(&v);
      const auto agree = std::count_if(v.begin(), v.end(),
                                       [&](float r) { return std::fabs(r - m) <= kAgree * m; });
      if (v.size() < 12 || agree < kMinAgreeing * v.size()) valid[static_cast<std::size_t>(i)] = 0;
      gain_.at<cv::Vec3f>(i / blocks_.width, i % blocks_.width)[c] = m;
    }
    if (valid[static_cast<std::size_t>(i)]) {
      const cv::Vec3f g = gain_.at<cv::Vec3f>(i / blocks_.width, i % blocks_.width);
      for (int c = 0; c < 3; ++c) all[static_cast<std::size_t>(c)].push_back(g[c]);
    }
  }
  cv::Vec3f fallback;
  for (int c = 0; c < 3; ++c) fallback[c] = Median(&all[static_cast<std::size_t>(c)]);
  RepairGrid(valid, fallback, &gain_);
  cv::resize(gain_, gain_map_, bgr.size(), 0, 0, cv::INTER_LINEAR);
}

void PixelModel::Compare(const cv::Mat& bgr, const cv::Rect& rect, const cv::Mat& ignore,
                         cv::Mat* person, cv::Mat* moved) {
  MeasureGain(bgr, ignore);
  const cv::Mat frame = bgr(rect), gain = gain_map_(rect), threshold = threshold_(rect);
  cv::multiply(standstill_f_(rect), gain, scaled_f_);
  scaled_f_.convertTo(scaled_, CV_8UC3);
  Exceeds(frame, scaled_, threshold, &diff_, &any_, moved);
  cv::multiply(background_f_(rect), gain, scaled_f_);
  scaled_f_.convertTo(scaled_, CV_8UC3);
  Exceeds(frame, scaled_, threshold, &diff_, &any_, person);
}

void PixelModel::SetThird(const cv::Mat& bgr) {
  const cv::Scalar g = GlobalGain(bgr, standstill_);
  bgr.convertTo(third_f_, CV_32FC3);
  cv::multiply(third_f_, cv::Scalar(1 / g[0], 1 / g[1], 1 / g[2]), third_f_);
}

void PixelModel::CompareThird(const cv::Mat& bgr, const cv::Rect& rect, cv::Mat* differs) {
  cv::multiply(third_f_(rect), gain_map_(rect), scaled_f_);
  scaled_f_.convertTo(scaled_, CV_8UC3);
  Exceeds(bgr(rect), scaled_, threshold_(rect), &diff_, &any_, differs);
}

void PixelModel::StandstillPerson(cv::Mat* mask) const {
  cv::Mat scaled, diff, any;
  cv::multiply(background_, standstill_gain_, scaled);
  Exceeds(standstill_, scaled, threshold_, &diff, &any, mask);
  ClearShadows(standstill_, scaled, noise_, mask);
}

void PixelModel::Differ(const cv::Mat& bgr, const cv::Mat& reference, cv::Mat* mask) const {
  // A pixel differs only from every reference pixel within one pixel of it: the image may come
  // from another encoder (a still) whose edges fall a little differently.
  cv::Mat scaled, padded, diff, any, one;
  cv::multiply(reference, GlobalGain(bgr, reference), scaled);
  cv::copyMakeBorder(scaled, padded, 1, 1, 1, 1, cv::BORDER_REPLICATE);
  *mask = cv::Mat(bgr.size(), CV_8UC1, cv::Scalar(255));
  for (int dy = 0; dy <= 2; ++dy) {
    for (int dx = 0; dx <= 2; ++dx) {
      Exceeds(bgr, padded(cv::Rect(dx, dy, bgr.cols, bgr.rows)), threshold_, &diff, &any, &one);
      *mask &= one;
    }
  }
  ClearShadows(bgr, scaled, noise_, mask);
}

}  // namespace armmimic::bgsub
