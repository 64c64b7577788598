#include "score_labels.h"

#include <algorithm>
#include <numeric>

namespace armmimic::gui {

std::vector<std::optional<ScoreLabel>> PlaceScoreLabels(const std::vector<QPointF>& dots,
                                                        const std::vector<double>& scores,
                                                        const QFontMetricsF& metrics, double unit) {
  std::vector<std::optional<ScoreLabel>> out(dots.size());
  std::vector<std::size_t> order(dots.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return scores[a] > scores[b]; });
  std::vector<QRectF> taken;
  const double dot = 2.0 * unit;
  for (const QPointF& d : dots)
    taken.push_back(QRectF(d - QPointF(dot, dot), QSizeF(2 * dot, 2 * dot)));
  for (std::size_t i : order) {
    ScoreLabel label;
    label.text = QString::number(scores[i], 'f', 2);
    const double w = metrics.horizontalAdvance(label.text), a = metrics.ascent(),
                 h = metrics.height(), gap = 3 * unit;
    const QPointF c = dots[i];
    const QPointF spots[] = {{c.x() + gap, c.y() - gap},
                             {c.x() + gap, c.y() + gap + a},
                             {c.x() - gap - w, c.y() - gap},
                             {c.x() - gap - w, c.y() + gap + a}};
    for (const QPointF& baseline : spots) {
      const QRectF rect(baseline.x(), baseline.y() - a, w, h);
      const bool free = std::none_of(taken.begin(), taken.end(),
                                     [&](const QRectF& t) { return t.intersects(rect); });
      if (!free) continue;
      label.baseline = baseline;
      label.rect = rect;
      taken.push_back(rect);
      out[i] = label;
      break;
    }
  }
  return out;
}

}  // namespace armmimic::gui
