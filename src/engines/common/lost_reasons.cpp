#include "armmimic/engines/lost_reasons.h"

#include <algorithm>
#include <cctype>

namespace armmimic {

std::string LostReasons::Reason(const std::string& note) {
  std::string text = note;
  for (const char* cut : {" (", "; "}) {
    const std::size_t at = text.find(cut);
    if (at != std::string::npos) text.erase(at);
  }
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto digit = [&](std::size_t k) {
      return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]));
    };
    // A number: digits with an optional fraction, and its sign when one stands before it.
    const bool sign = (text[i] == '-' || text[i] == '+') && digit(i + 1) &&
                      (i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1])));
    if (digit(i) || sign) {
      std::size_t k = sign ? i + 1 : i;
      while (digit(k)) ++k;
      if (k + 1 < text.size() && text[k] == '.' && digit(k + 1)) {
        ++k;
        while (digit(k)) ++k;
      }
      out += 'N';
      i = k;
    } else {
      out += text[i++];
    }
  }
  while (!out.empty() && std::isspace(static_cast<unsigned char>(out.back()))) out.pop_back();
  return out.empty() ? "no reason given" : out;
}

void LostReasons::Add(const ArmMeasurement& m) {
  for (const ArmMeasurement* arm : m.Arms()) {
    if (arm->phase != MeasurementPhase::kLost) continue;
    ++counts_[Reason(arm->note)];
  }
}

int LostReasons::lost() const {
  int n = 0;
  for (const auto& [reason, count] : counts_) n += count;
  return n;
}

std::vector<std::pair<std::string, int>> LostReasons::Ranked() const {
  std::vector<std::pair<std::string, int>> ranked(counts_.begin(), counts_.end());
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  return ranked;
}

std::string LostReasons::Text(std::size_t top) const {
  const std::vector<std::pair<std::string, int>> ranked = Ranked();
  std::string text;
  int shown = 0;
  for (std::size_t i = 0; i < ranked.size() && i < top; ++i) {
    text += (text.empty() ? "" : "; ") + ranked[i].first + " (" + std::to_string(ranked[i].second) +
            ")";
    shown += ranked[i].second;
  }
  const int all = lost();
  if (shown < all) {
    const std::size_t others = ranked.size() - top;
    text += "; " + std::to_string(others) + " other reason" + (others == 1 ? "" : "s") + " (" +
            std::to_string(all - shown) + ")";
  }
  return text;
}

}  // namespace armmimic
