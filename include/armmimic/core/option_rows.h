// Builders for the rows of an option table (option_table.h), used where a table is defined:
// Int, Real, Bool, Enum and Text make a row from the key, the struct member (or a getter and a
// setter), the default, the range, the label and the help; chained calls set what most rows
// leave at its default (group, unit, flag, step, relations).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "armmimic/core/option_table.h"

namespace armmimic::option_rows {

constexpr double kNoMax = std::numeric_limits<double>::infinity();

template <typename O>
struct Row {
  OptionField<O> f;
  Row& Main() { return Group(OptionGroup::kMain); }
  Row& Input() { return Group(OptionGroup::kInput); }
  Row& Group(OptionGroup g) {
    f.group = g;
    return *this;
  }
  Row& Step(double step) {
    f.step = step;
    return *this;
  }
  Row& Unit(const char* unit) {
    f.unit = unit;
    return *this;
  }
  // The command-line flag that sets this field.
  Row& Flag(const char* flag) {
    f.flag = flag;
    return *this;
  }
  // The lower bound is exclusive: the value must be above it.
  Row& AboveMin() {
    f.min_exclusive = true;
    return *this;
  }
  // Check() wants this field <= (strict: <) the field `key`.
  Row& Below(const char* key, bool strict = false) {
    f.below = key;
    f.strictly_below = strict;
    return *this;
  }
  operator OptionField<O>() const { return f; }  // NOLINT: rows convert into the table
};

template <typename O>
Row<O> Base(const char* key, OptionKind kind, double def, double lo, double hi, const char* label,
            const char* help) {
  Row<O> r;
  r.f.key = key;
  r.f.kind = kind;
  r.f.default_value = def;
  r.f.min = lo;
  r.f.max = hi;
  r.f.label = label;
  r.f.help = help;
  return r;
}

template <typename O>
Row<O> Int(const char* key, int O::*m, int def, int lo, int hi, const char* label,
           const char* help) {
  Row<O> r = Base<O>(key, OptionKind::kInt, def, lo, hi, label, help);
  r.f.get = [m](const O& o) { return static_cast<double>(o.*m); };
  r.f.set = [m](O& o, double v) { o.*m = static_cast<int>(std::lround(v)); };
  return r;
}

template <typename O>
Row<O> Real(const char* key, double O::*m, double def, double lo, double hi, int decimals,
            const char* label, const char* help) {
  Row<O> r = Base<O>(key, OptionKind::kDouble, def, lo, hi, label, help);
  r.f.decimals = decimals;
  r.f.step = std::pow(10.0, -std::max(0, decimals - 1));
  r.f.get = [m](const O& o) { return o.*m; };
  r.f.set = [m](O& o, double v) { o.*m = v; };
  return r;
}

template <typename O>
Row<O> Bool(const char* key, bool O::*m, bool def, const char* label, const char* help) {
  Row<O> r = Base<O>(key, OptionKind::kBool, def ? 1 : 0, 0, 1, label, help);
  r.f.get = [m](const O& o) { return o.*m ? 1.0 : 0.0; };
  r.f.set = [m](O& o, double v) { o.*m = v != 0; };
  return r;
}

template <typename O, typename E>
Row<O> Enum(const char* key, E O::*m, E def, const std::vector<std::string>& choices,
            const char* label, const char* help) {
  Row<O> r = Base<O>(key, OptionKind::kEnum, static_cast<int>(def), 0,
                     static_cast<double>(choices.size()) - 1, label, help);
  r.f.choices = choices;
  r.f.get = [m](const O& o) { return static_cast<double>(static_cast<int>(o.*m)); };
  r.f.set = [m](O& o, double v) { o.*m = static_cast<E>(static_cast<int>(std::lround(v))); };
  return r;
}

// A bool member shown as a choice of two names: `if_true` for true, `if_false` for false
// (e.g. J2 from "elevation" or "upper").
template <typename O>
Row<O> Choice(const char* key, bool O::*m, bool def, const std::string& if_false,
              const std::string& if_true, const char* label, const char* help) {
  Row<O> r = Base<O>(key, OptionKind::kEnum, def ? 1 : 0, 0, 1, label, help);
  r.f.choices = {if_false, if_true};
  r.f.get = [m](const O& o) { return o.*m ? 1.0 : 0.0; };
  r.f.set = [m](O& o, double v) { o.*m = std::lround(v) != 0; };
  return r;
}

// A value with its own syntax: `format` writes it, `parse` reads it (an error text, or "").
template <typename O, typename Format, typename Parse>
Row<O> Text(const char* key, const char* def, Format format, Parse parse, const char* label,
            const char* help) {
  Row<O> r = Base<O>(key, OptionKind::kText, 0, 0, 0, label, help);
  r.f.default_text = def;
  r.f.format = format;
  r.f.parse = parse;
  return r;
}

}  // namespace armmimic::option_rows
