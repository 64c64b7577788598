// Number helpers shared by the VAL program's reader and writer (val_program.cpp) and its safety
// check (val_check.cpp). Private to the robot layer.
#pragma once

#include <string>
#include <vector>

namespace armmimic::robot::val_text {

// Plain decimal numbers only ([+-]digits[.digits]): no exponent, hex, inf or nan, so the value
// checked is the value any controller reads.
bool ParseDouble(const std::string& text, double* out);

// Comma-separated plain decimals (see ParseDouble); false on an empty list or a trailing comma.
bool ParseList(const std::string& text, std::vector<double>* out);

// Short form for messages: up to three decimals, trailing zeros dropped.
std::string Num(double v);

}  // namespace armmimic::robot::val_text
