// Option tables: every setting a user can change, described once. One table per settings struct
// (the engines' options, the planner, the mapping, the joint limits, the link and the port); each
// row holds the key, the kind, the documented default, the range, the unit, the help, the group,
// the command-line flag where there is one, and how to read and write the value in its struct.
// From the tables come the structs' range checks, the CLI flags and their help, the GUI forms,
// the saved settings and the file headers that record a run (docs/architecture.md, "Option
// tables"). Qt-free, so the engines and the robot layer use it too; rows are built with the
// helpers of option_rows.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "armmimic/core/status.h"

namespace armmimic {

// kText: a value with its own syntax ("J1=-90:90", "-1,0", "45,45,45,90,90,90"), read and
// written by the row's parse and format functions.
enum class OptionKind { kInt, kDouble, kBool, kEnum, kText };

// kMain: shown first; kAdvanced: in a folded "Advanced" section.
enum class OptionGroup { kMain, kAdvanced };

template <typename Options>
struct OptionField {
  std::string key;    // the struct member's name ("max_corners"): settings key, widget name
  std::string label;  // short, for a form row
  std::string help;   // one line, in the library's words (the shells add a flag or field)
  std::string unit;   // "deg", "s", "Hz", "px", "deg/s"; "" for counts, ratios and switches
  std::string flag;   // the command-line flag that sets it ("--cutoff"), "" where there is none
  OptionKind kind = OptionKind::kDouble;
  OptionGroup group = OptionGroup::kAdvanced;
  double min = 0;  // inclusive (exclusive with min_exclusive); bool 0..1; enum 0..choices-1
  double max = 0;  // inclusive; +infinity: no upper bound
  bool min_exclusive = false;
  double default_value = 0;  // the documented default (kText: see default_text)
  int decimals = 0;          // kDouble: digits shown
  double step = 1;           // editor step (2 for odd-only windows)
  // Relations Check() enforces between two fields: this one must be <= (or <) field `below`.
  // A breach is keyed by the `below` field, or by this one with below_keys_self (where this is
  // the setting people change: marker.low against marker.high).
  std::string below;
  bool strictly_below = false;
  bool below_keys_self = false;
  std::vector<std::string> choices;  // kEnum: value names in enum order (value = index)
  // Values cross as double: ints are rounded, bools are 0/1, enums are the choice index.
  std::function<double(const Options&)> get;
  std::function<void(Options&, double)> set;
  // kText only: the value as text, and the text read into the struct (an error text, or "").
  std::string default_text;
  std::function<std::string(const Options&)> format;
  std::function<std::string(const std::string&, Options*)> parse;
};

// The field named `key` in `fields`, or nullptr.
template <typename Options>
const OptionField<Options>* FindOptionField(const std::vector<OptionField<Options>>& fields,
                                            const std::string& key) {
  for (const auto& f : fields) {
    if (f.key == key) return &f;
  }
  return nullptr;
}

// A number in its shortest form for people (0.300000 -> 0.3), and exactly (it reads back the
// same double: the file headers record values this way).
std::string OptionNumberText(double v);
std::string OptionExactNumberText(double v);
// true/false/on/off/1/0, any case.
bool ParseOptionBool(const std::string& text, bool* out);
// A finite number with '.' decimals whatever the locale.
bool ParseOptionNumber(const std::string& text, double* out);

// The value `v` of a non-text field for people: "true", "auto", "200", "0.3".
template <typename O>
std::string OptionValueText(const OptionField<O>& f, double v) {
  switch (f.kind) {
    case OptionKind::kBool:
      return v != 0 ? "true" : "false";
    case OptionKind::kEnum:
      return f.choices[static_cast<std::size_t>(v)];
    case OptionKind::kInt:
      return std::to_string(static_cast<long long>(std::lround(v)));
    case OptionKind::kDouble:
    case OptionKind::kText:
      break;
  }
  return OptionNumberText(v);
}

// The value of `f` in `o` as text that SetOptionText reads back exactly.
template <typename O>
std::string OptionExactText(const OptionField<O>& f, const O& o) {
  if (f.kind == OptionKind::kText) return f.format(o);
  if (f.kind == OptionKind::kDouble) return OptionExactNumberText(f.get(o));
  return OptionValueText(f, f.get(o));
}

// The documented default of `f` for people.
template <typename O>
std::string OptionDefaultText(const OptionField<O>& f) {
  return f.kind == OptionKind::kText ? f.default_text : OptionValueText(f, f.default_value);
}

// What `f` accepts, for a message: "a whole number in [1, 254]", "true or false", ...
template <typename O>
std::string OptionAccepts(const OptionField<O>& f) {
  switch (f.kind) {
    case OptionKind::kBool:
      return "true or false";
    case OptionKind::kEnum: {
      std::string names;
      for (const std::string& c : f.choices) names += (names.empty() ? "" : ", ") + c;
      return "one of " + names;
    }
    case OptionKind::kText:
      return "its documented form";
    case OptionKind::kInt:
      return "a whole number in [" + OptionValueText(f, f.min) + ", " + OptionValueText(f, f.max) +
             "]";
    case OptionKind::kDouble:
      break;
  }
  if (std::isinf(f.max)) {
    return std::string("a number ") + (f.min_exclusive ? "> " : ">= ") + OptionValueText(f, f.min);
  }
  return "a number in [" + OptionValueText(f, f.min) + ", " + OptionValueText(f, f.max) + "]";
}

// Whether the number `v` lies in the range of `f` (finite; whole for ints).
template <typename O>
bool OptionInRange(const OptionField<O>& f, double v) {
  if (!std::isfinite(v)) return false;
  if (f.min_exclusive ? !(v > f.min) : !(v >= f.min)) return false;
  if (!std::isinf(f.max) && !(v <= f.max)) return false;
  return f.kind != OptionKind::kInt || v == std::floor(v);
}

// Reads `text` into the field `f` of `o`. `name` names the setting in the message
// ("lk.max_corners"), which is also the error's key.
template <typename O>
Status SetOptionText(const OptionField<O>& f, const std::string& name, const std::string& text,
                     O* o) {
  double v = 0;
  bool ok = false;
  if (f.kind == OptionKind::kText) {
    const std::string error = f.parse(text, o);
    if (error.empty()) return Status::Ok();
    return Status::Error(name, name + " '" + text + "': " + error);
  }
  if (f.kind == OptionKind::kBool) {
    bool b = false;
    ok = ParseOptionBool(text, &b);
    v = b ? 1 : 0;
  } else if (f.kind == OptionKind::kEnum) {
    const auto it = std::find(f.choices.begin(), f.choices.end(), text);
    ok = it != f.choices.end();
    v = static_cast<double>(it - f.choices.begin());
  } else {
    ok = ParseOptionNumber(text, &v) && OptionInRange(f, v);
  }
  if (!ok) return Status::Error(name, name + " '" + text + "': expected " + OptionAccepts(f));
  f.set(*o, v);
  return Status::Ok();
}

// The label of a row as a noun in a sentence: "Max. interval" -> "max. interval".
std::string OptionNoun(const std::string& label);

// A value a check refused, for its message: the shortest form that is exactly `v` ("0.3",
// "1e-05", "nan").
std::string OptionRefusedNumberText(double v);

// The value `v` of the number row `f` with its unit, for a message: "-1 Hz", "4", "0.5 s".
template <typename O>
std::string OptionRefusedText(const OptionField<O>& f, double v) {
  const std::string text =
      f.kind == OptionKind::kInt ? OptionValueText(f, v) : OptionRefusedNumberText(v);
  return f.unit.empty() ? text : text + " " + f.unit;
}

// The range checks of a settings struct: every numeric field of `fields` in its range, and the
// relations between fields (rules of another shape stay in the struct's Check(), after these).
// Errors carry the key "<table>.<key>", repeat the refused value and say what the setting must
// be, in the table's words ("cutoff is -1 Hz; it must be >= 0 Hz").
template <typename O>
Status CheckOptionFields(const std::vector<OptionField<O>>& fields, const std::string& table,
                         const O& o) {
  for (const auto& f : fields) {
    if (f.kind != OptionKind::kInt && f.kind != OptionKind::kDouble) continue;
    const double v = f.get(o);
    if (OptionInRange(f, v)) continue;
    std::string must = f.kind == OptionKind::kInt ? "a whole number " : "";
    if (std::isinf(f.max)) {
      must += std::string(f.min_exclusive ? "> " : ">= ") + OptionValueText(f, f.min);
    } else {
      must += "in [" + OptionValueText(f, f.min) + ", " + OptionValueText(f, f.max) + "]";
    }
    return Status::Error(table + "." + f.key, OptionNoun(f.label) + " is " +
                                                  OptionRefusedText(f, v) + "; it must be " + must +
                                                  (f.unit.empty() ? "" : " " + f.unit));
  }
  for (const auto& f : fields) {
    if (f.below.empty()) continue;
    const OptionField<O>* upper = FindOptionField(fields, f.below);
    if (!upper) continue;
    const double v = f.get(o);
    const double u = upper->get(o);
    if (f.strictly_below ? v < u : v <= u) continue;
    if (f.below_keys_self) {
      return Status::Error(table + "." + f.key,
                           OptionNoun(f.label) + " " + OptionValueText(f, v) +
                               (f.strictly_below ? " is not below the " : " is above the ") +
                               OptionNoun(upper->label) + " " + OptionValueText(*upper, u));
    }
    return Status::Error(
        table + "." + upper->key,
        OptionNoun(upper->label) + " is " + OptionRefusedText(*upper, u) +
            (f.strictly_below ? "; it must be above the " : "; it must not be below the ") +
            OptionNoun(f.label) + " " + OptionRefusedText(f, v));
  }
  return Status::Ok();
}

}  // namespace armmimic
