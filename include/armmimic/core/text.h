// Small text helpers shared by the file readers (angle files, truth files, controller profiles,
// VAL programs) and the command line: locale-independent number parsing, TSV fields, trimming
// and the percent-encoding of meta values.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <iosfwd>
#include <string>
#include <vector>

namespace armmimic {

// Splits a line at every TAB (an empty line gives one empty field).
std::vector<std::string> SplitTabs(const std::string& line);

// A table field: a finite plain decimal ('.' decimals, optional exponent, no leading '+', no
// "inf"/"0x"), or "nan" when `allow_nan`.
bool ParseTableNumber(const std::string& field, bool allow_nan, double* out);

// A frame index: a non-negative decimal integer of at most 10 digits.
bool ParseFrameIndex(const std::string& field, int* out);

// A finite number as std::from_chars reads it, with an optional leading '+', whatever the locale.
bool ParseFiniteDouble(const std::string& text, double* out);

// Removes a UTF-8 byte order mark (EF BB BF) at the start of `line`, as a spreadsheet or an
// editor on Windows writes one at the start of a file. Every reader calls it on its first line.
void StripUtf8Bom(std::string* line);
// Reads one line of `in` into `*line`. A line ends at LF, CRLF or a CR alone (as old Mac editors
// end lines); the end is not kept. false when the input has no more characters. A line longer
// than `max_length` keeps only its first max_length + 1 characters, the rest is read past, and
// `*too_long` is set (it is never cleared).
bool ReadTextLine(std::istream& in, std::string* line, std::size_t max_length = std::string::npos,
                  bool* too_long = nullptr);

// Removes spaces, tabs and CRs at both ends.
std::string Trim(const std::string& text);

// Meta values in a "# key=value" line: space, '%', TAB, LF and CR as %20 %25 %09 %0A %0D.
std::string PercentEncode(const std::string& value);
std::string PercentDecode(const std::string& value);

// A piece of a file's text for a message: on one line whatever it holds (TAB, LF, CR and other
// control bytes as \t, \n, \r, \xNN) and at most `max_chars` of it, a longer text cut with
// "... (N characters)". A message never prints more than one line of the file it is about.
std::string Excerpt(const std::string& text, std::size_t max_chars = 60);

// A field of a table that other programs read by TAB and line (the batch summary): backslash,
// TAB, LF and CR as \\, \t, \n, \r; everything else (spaces, UTF-8) as it is.
// UnescapeTsvField reverses it (an unknown or lone backslash stays as it is).
std::string EscapeTsvField(const std::string& text);
std::string UnescapeTsvField(const std::string& field);

// The system's text for an errno value ("No such file or directory"), the same as std::strerror
// gives but safe to call from several threads at once (analyses run on worker threads).
std::string ErrnoText(int err);

// The value among `values` whose name (`name_of(value)`) is `name`, into *out; false (and *out
// unchanged) when none is. For enums whose names are their one spelling in files and flags.
template <typename E, typename NameOf>
bool ParseByName(const std::string& name, std::initializer_list<E> values, NameOf name_of, E* out) {
  for (E v : values) {
    if (name == name_of(v)) {
      *out = v;
      return true;
    }
  }
  return false;
}

}  // namespace armmimic
