#include "robustness_report.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>

namespace armmimic::bench {
namespace {

std::string Knob(const AngleMeta& knobs, const std::string& key) {
  for (const auto& [k, v] : knobs) {
    if (k == key) return v;
  }
  return "";
}

double KnobNum(const AngleMeta& knobs, const std::string& key) {
  const std::string v = Knob(knobs, key);
  return v.empty() ? 0.0 : std::strtod(v.c_str(), nullptr);
}

std::string Fmt(double v, int decimals, const char* unit = "") {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f%s", decimals, v, unit);
  return buf;
}

std::string Pct(double share, int decimals = 1) { return Fmt(100 * share, decimals, " %"); }

struct Feature {
  const char* name;
  std::function<bool(const AngleMeta&)> has;
};

const std::vector<Feature>& Features() {
  auto is = [](const char* key, const char* value) {
    return [key, value](const AngleMeta& k) { return Knob(k, key) == value; };
  };
  auto at_least = [](const char* key, double v) {
    return [key, v](const AngleMeta& k) { return std::fabs(KnobNum(k, key)) >= v; };
  };
  static const std::vector<Feature> features = {
      {"all scenes", [](const AngleMeta&) { return true; }},
      {"short sleeves", is("sleeves", "short")},
      {"bare skin close to the wall (distance < 60)",
       [](const AngleMeta& k) {
         return Knob(k, "sleeves") == "short" && KnobNum(k, "skin_wall_distance") < 60;
       }},
      {"camouflage: object behind the arm", is("camouflage", "object")},
      {"camouflage: sleeve close to the wall", is("camouflage", "wall")},
      {"camouflage: sleeve in the shirt's cloth across it", is("camouflage", "shirt")},
      {"sleeve of another cloth than the shirt", is("sleeve_match", "distinct")},
      {"hand beside the head", is("hand_by_head", "yes")},
      {"hand above the head", is("hand_above_head", "yes")},
      {"forearm across the torso", is("across_torso", "yes")},
      {"off-centre (>= 0.15 of the width)", at_least("offcentre", 0.15)},
      {"large arm (>= 45 % of the height)", at_least("arm_fraction", 0.45)},
      {"small arm (< 30 % of the height)",
       [](const AngleMeta& k) { return KnobNum(k, "arm_fraction") < 0.3; }},
      {"arm on the left of the image", is("side", "left")},
      {"fast (a step >= 10 deg a frame)", at_least("max_step_deg", 10)},
      {"furniture behind the arm", is("furniture_behind_arm", "yes")},
      {"moving shadow", is("shadow", "yes")},
      {"body sway >= 1.5 px", at_least("sway_px", 1.5)},
      {"JPEG quality <= 40", [](const AngleMeta& k) { return KnobNum(k, "jpeg_quality") <= 40; }},
      {"noise sigma >= 6", at_least("noise", 6)},
      {"lighting drift >= 0.25", at_least("drift", 0.25)},
  };
  return features;
}

}  // namespace

std::string SceneTsv(const std::vector<SceneResult>& scenes, const std::vector<RunSpec>& specs) {
  std::string out =
      "seed\ttier\tengine\tmode\tcoverage\tmean_error_deg\tworst_error_deg\tconfidently_wrong"
      "\tmotion_frames\tok_frames\tlost_reason\terror";
  if (!scenes.empty()) {
    for (const auto& kv : scenes.front().knobs) out += "\t" + kv.first;
  }
  out += "\n";
  for (const SceneResult& s : scenes) {
    for (std::size_t i = 0; i < specs.size() && i < s.runs.size(); ++i) {
      const RunResult& r = s.runs[i];
      out += std::to_string(s.seed) + "\t" + synth::SceneTierName(s.tier) + "\t" +
             EngineName(specs[i].engine) + "\t" + specs[i].mode->name + "\t" +
             Fmt(r.score.coverage(), 4) + "\t" + Fmt(r.score.mean_error_deg, 3) + "\t" +
             Fmt(r.score.worst_error_deg, 2) + "\t" +
             std::to_string(r.score.confidently_wrong_frames) + "\t" +
             std::to_string(r.score.motion_frames) + "\t" + std::to_string(r.score.ok_frames) +
             "\t" + (r.lost_reason.empty() ? "-" : r.lost_reason) + "\t" +
             (r.error.empty() ? "-" : r.error);
      for (const auto& kv : s.knobs) out += "\t" + kv.second;
      out += "\n";
    }
  }
  return out;
}

std::string FrameTsv(const std::vector<SceneResult>& scenes, const std::vector<RunSpec>& specs) {
  std::string out =
      "seed\ttier\tengine\tmode\tframe\tstatus\tconfidence\terr_upper\terr_fore\tnote\n";
  for (const SceneResult& s : scenes) {
    for (std::size_t i = 0; i < specs.size() && i < s.runs.size(); ++i) {
      const std::string head = std::to_string(s.seed) + "\t" + synth::SceneTierName(s.tier) + "\t" +
                               EngineName(specs[i].engine) + "\t" + specs[i].mode->name;
      for (const FrameRecord& f : s.runs[i].frames) {
        std::string note = f.note;
        for (char& c : note) {
          if (c == '\t' || c == '\n') c = ' ';
        }
        out += head + "\t" + std::to_string(f.frame) + "\t" + (f.ok ? "ok" : "lost") + "\t" +
               Fmt(f.confidence, 3) + "\t" + Fmt(f.err_upper, 2) + "\t" + Fmt(f.err_fore, 2) +
               "\t" + (note.empty() ? "-" : note) + "\n";
      }
    }
  }
  return out;
}

std::string SummaryTable(const std::vector<SceneResult>& scenes, const std::vector<RunSpec>& specs,
                         const std::vector<synth::SceneTier>& tiers) {
  std::string out =
      "| engine / mode | tier | scenes | median | p90 | max | coverage | worst scene | "
      "confidently wrong | zero coverage |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < specs.size(); ++i) {
    std::vector<std::pair<std::string, std::vector<synth::MotionScore>>> groups;
    for (synth::SceneTier t : tiers) groups.push_back({synth::SceneTierName(t), {}});
    if (tiers.size() > 1) groups.push_back({"all", {}});
    for (const SceneResult& s : scenes) {
      for (std::size_t g = 0; g < tiers.size(); ++g) {
        if (tiers[g] == s.tier) groups[g].second.push_back(s.runs[i].score);
      }
      if (tiers.size() > 1) groups.back().second.push_back(s.runs[i].score);
    }
    for (const auto& [tier, runs] : groups) {
      const synth::RobustnessSummary r = synth::SummariseRobustness(runs);
      out += "| " + specs[i].Name() + " | " + tier + " | " + std::to_string(r.scenes) + " | " +
             Fmt(r.median_deg, 2, "°") + " | " + Fmt(r.p90_deg, 2, "°") + " | " +
             Fmt(r.max_deg, 1, "°") + " | " + Pct(r.coverage) + " | " + Pct(r.worst_coverage, 0) +
             " | " + Pct(r.confidently_wrong_rate, 2) + " | " +
             std::to_string(r.zero_coverage_scenes) + " |\n";
    }
  }
  return out;
}

std::string FeatureTable(const std::vector<SceneResult>& scenes,
                         const std::vector<RunSpec>& specs) {
  std::string out = "| scene feature | scenes |";
  std::string rule = "|---|---|";
  for (const RunSpec& s : specs) {
    out += " " + s.Name() + " |";
    rule += "---|";
  }
  out += "\n" + rule + "\n";
  for (const Feature& f : Features()) {
    std::vector<std::vector<synth::MotionScore>> runs(specs.size());
    int n = 0;
    for (const SceneResult& s : scenes) {
      if (!f.has(s.knobs)) continue;
      ++n;
      for (std::size_t i = 0; i < specs.size(); ++i) runs[i].push_back(s.runs[i].score);
    }
    if (n == 0) continue;
    out += std::string("| ") + f.name + " | " + std::to_string(n) + " |";
    for (const auto& r : runs) {
      const synth::RobustnessSummary m = synth::SummariseRobustness(r);
      out += " " + Pct(m.coverage, 0) + " · " + Pct(m.confidently_wrong_rate, 1) + " · " +
             Fmt(m.median_deg, 1, "°") +
             (m.zero_coverage_scenes ? " · " + std::to_string(m.zero_coverage_scenes) + " empty"
                                     : std::string()) +
             " |";
    }
    out += "\n";
  }
  return out;
}

}  // namespace armmimic::bench
