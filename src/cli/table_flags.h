// Command-line flags registered from their option-table rows (armmimic/core/option_table.h): the
// flag, the help, the default and the range come from the row, so each is written once, in its
// table. A command adds only what is its own: which engines read the flag, a metavar where the
// row's unit says nothing, or where the default comes from besides the row ("or the --profile
// file's").
//
// Values are read by the row's kind: a whole number must lie in the row's range at once (as
// ArgParser::Int refuses it); any other number is taken as given and its range is the struct's
// Check(), whose message repeats the value and is worded with the flag (Worded); a choice is one
// of the row's names; text is read by the row's own parser.
#pragma once

#include <cctype>
#include <functional>
#include <string>

#include "args.h"
#include "armmimic/core/option_table.h"

namespace armmimic::cli {

// What a command says about a row's flag besides the row.
struct RowFlagWords {
  std::string metavar;         // "": the row's unit in capitals, N, X, the choices a|b, or VALUE
  std::string prefix;          // before the row's help: "bgsub: ", "bgsub/lk: "
  const char* help = nullptr;  // replaces the row's help (mimic's causal planner)
  std::string default_note;    // after the default: " or the --profile file's"
};

// Words that give only a metavar ("FILE", "SIGN,OFFSET").
inline RowFlagWords WithMetavar(const char* metavar) {
  RowFlagWords w;
  w.metavar = metavar;
  return w;
}

template <typename O>
std::string RowMetavar(const OptionField<O>& f, const RowFlagWords& w = {}) {
  if (!w.metavar.empty()) return w.metavar;
  std::string out;
  for (char c : f.unit) out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (!out.empty()) return out;
  switch (f.kind) {
    case OptionKind::kInt:
      return "N";
    case OptionKind::kDouble:
      return "X";
    case OptionKind::kEnum:
      for (const std::string& c : f.choices) out += (out.empty() ? "" : "|") + c;
      return out;
    case OptionKind::kBool:
    case OptionKind::kText:
      break;
  }
  return "VALUE";
}

// "<prefix><help> (default <default><note>)"; no default part when the default is empty, or for
// a switch (off unless given).
template <typename O>
std::string RowHelp(const OptionField<O>& f, const RowFlagWords& w = {}) {
  const std::string def = f.kind == OptionKind::kBool ? "" : OptionDefaultText(f);
  return w.prefix + (w.help ? std::string(w.help) : f.help) +
         (def.empty() ? "" : " (default " + def + w.default_note + ")");
}

// "a, b or c": the row's choices for a message.
template <typename O>
std::string RowChoicesText(const OptionField<O>& f) {
  std::string out;
  for (std::size_t i = 0; i < f.choices.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == f.choices.size() ? " or " : ", ") + f.choices[i];
  }
  return out;
}

// Reads `value` into the row `f` of `*o` (see the top of this file). An error text, or "".
template <typename O>
std::string ParseRowValue(const OptionField<O>& f, const std::string& value, O* o) {
  switch (f.kind) {
    case OptionKind::kInt: {
      int n = 0;
      if (!ParseIntArg(value, &n)) return "'" + value + "' is not a whole number";
      if (!OptionInRange(f, n)) {
        return "'" + value + "' is out of range [" + OptionValueText(f, f.min) + ", " +
               OptionValueText(f, f.max) + "]";
      }
      f.set(*o, n);
      return "";
    }
    case OptionKind::kDouble: {
      double d = 0;
      if (!ParseDoubleArg(value, &d)) return "'" + value + "' is not a number (use '.' decimals)";
      f.set(*o, d);
      return "";
    }
    case OptionKind::kEnum:
      for (std::size_t i = 0; i < f.choices.size(); ++i) {
        if (f.choices[i] == value) {
          f.set(*o, static_cast<double>(i));
          return "";
        }
      }
      return "'" + value + "' is not " + RowChoicesText(f);
    case OptionKind::kText: {
      // The parsers' messages mostly quote the value; one that does not gets it in front.
      const std::string error = f.parse(value, o);
      if (error.empty() || error.find("'" + value + "'") != std::string::npos) return error;
      return "'" + value + "': " + error;
    }
    case OptionKind::kBool:
      break;
  }
  bool b = false;
  if (!ParseOptionBool(value, &b)) return "'" + value + "' is not true or false";
  f.set(*o, b ? 1 : 0);
  return "";
}

// The flag of the row `f` (a table's static row), read into `*o`. A switch row (bool) is a flag
// without a value that sets it.
template <typename O>
void AddRowFlag(ArgParser& p, const OptionField<O>& f, O* o, const RowFlagWords& w = {}) {
  const OptionField<O>* row = &f;
  if (f.kind == OptionKind::kBool) {
    p.Switch(f.flag, RowHelp(f, w), [row, o] { row->set(*o, 1); });
    return;
  }
  p.Custom(f.flag, RowMetavar(f, w), RowHelp(f, w),
           [row, o](const std::string& v) { return ParseRowValue(*row, v, o); });
}

}  // namespace armmimic::cli
