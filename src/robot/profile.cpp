#include "armmimic/robot/profile.h"
#include "armmimic/core/text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "armmimic/core/angle_file.h"

namespace armmimic::robot {
namespace {

bool ParseInt(const std::string& text, int* out) {
  if (text.empty()) return false;
  int v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v, 10);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size()) return false;
  *out = v;
  return true;
}

// Decodes \r \n \t \\ escapes; returns false on an unknown escape.
bool Unescape(const std::string& text, std::string* out) {
  std::string s;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\') {
      s += text[i];
      continue;
    }
    if (++i == text.size()) return false;
    switch (text[i]) {
      case 'r':
        s += '\r';
        break;
      case 'n':
        s += '\n';
        break;
      case 't':
        s += '\t';
        break;
      case '\\':
        s += '\\';
        break;
      default:
        return false;
    }
  }
  *out = s;
  return true;
}

std::string Escape(const std::string& text) {
  std::string s;
  for (char c : text) {
    switch (c) {
      case '\r':
        s += "\\r";
        break;
      case '\n':
        s += "\\n";
        break;
      case '\t':
        s += "\\t";
        break;
      case '\\':
        s += "\\\\";
        break;
      default:
        s += c;
    }
  }
  return s;
}

// Placeholders a template may use, per key.
const std::map<std::string, std::set<std::string>>& TemplatePlaceholders() {
  static const std::map<std::string, std::set<std::string>> m = {
      {"speed_template", {"speed"}},
      {"move_template", {"j1", "j2", "j3", "j4", "j5", "j6"}},
      {"program_move_template", {"j1", "j2", "j3", "j4", "j5", "j6"}},
      {"drive_template", {"joint", "change", "speed"}},
      {"edit_template", {"name"}},
      {"execute_template", {"name"}},
  };
  return m;
}

// Checks that `text` uses only `allowed` placeholders and every required one of them.
std::string CheckTemplate(const std::string& key, const std::string& text) {
  const std::set<std::string>& allowed = TemplatePlaceholders().at(key);
  std::set<std::string> used;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '}') return key + ": unmatched '}'";
    if (text[i] != '{') continue;
    const auto close = text.find('}', i);
    if (close == std::string::npos) return key + ": unmatched '{'";
    const std::string name = text.substr(i + 1, close - i - 1);
    if (!allowed.count(name)) return key + ": unknown placeholder {" + name + "}";
    used.insert(name);
    i = close;
  }
  for (const std::string& name : allowed) {
    if (!used.count(name)) return key + ": missing placeholder {" + name + "}";
  }
  return "";
}

struct Field {
  std::function<std::string(const std::string& value, ControllerProfile* p)> set;
  std::function<std::string(const ControllerProfile& p)> get;
  const char* doc;
};

using FieldList = std::vector<std::pair<std::string, Field>>;

Field StringField(std::string ControllerProfile::*member, const char* doc) {
  return {[member](const std::string& v, ControllerProfile* p) {
            std::string s;
            if (!Unescape(v, &s)) return std::string("bad escape (use \\r, \\n, \\t or \\\\)");
            p->*member = s;
            return std::string();
          },
          [member](const ControllerProfile& p) { return Escape(p.*member); }, doc};
}

// `decimals` fixed decimals when that reads back as the same value, else the shortest text that
// does (a speed of 0.0012 must not be written as "0.0", which the reader refuses).
std::string FormatExact(double v, int decimals) {
  std::string s = FormatNumber(v, decimals);
  double back = 0;
  if (ParseFiniteDouble(s, &back) && back == v) return s;
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, r.ptr);
}

Field DoubleField(double ControllerProfile::*member, const char* doc) {
  return {[member](const std::string& v, ControllerProfile* p) {
            double d = 0;
            if (!ParseFiniteDouble(v, &d)) return "'" + v + "' is not a number";
            p->*member = d;
            return std::string();
          },
          [member](const ControllerProfile& p) { return FormatExact(p.*member, 3); }, doc};
}

Field IntField(int ControllerProfile::*member, const char* doc) {
  return {[member](const std::string& v, ControllerProfile* p) {
            int d = 0;
            if (!ParseInt(v, &d)) return "'" + v + "' is not a whole number";
            p->*member = d;
            return std::string();
          },
          [member](const ControllerProfile& p) { return std::to_string(p.*member); }, doc};
}

const FieldList& Fields() {
  static const FieldList fields = {
      {"name", StringField(&ControllerProfile::name, "a label shown in messages")},
      {"terminator",
       StringField(&ControllerProfile::terminator, "written after every line (\\r = CR)")},
      {"prompt_top", StringField(&ControllerProfile::prompt_top,
                                 "a received line exactly this: the monitor prompt")},
      {"prompt_running", StringField(&ControllerProfile::prompt_running,
                                     "a received line exactly this: prompt while a program runs")},
      {"error_prefix", StringField(&ControllerProfile::error_prefix,
                                   "a received line starting with this, then text: an error")},
      {"echo",
       {[](const std::string& v, ControllerProfile* p) {
          if (v == "yes" || v == "true" || v == "1") {
            p->echo = true;
          } else if (v == "no" || v == "false" || v == "0") {
            p->echo = false;
          } else {
            return "'" + v + "' is not yes or no";
          }
          return std::string();
        },
        [](const ControllerProfile& p) { return std::string(p.echo ? "yes" : "no"); },
        "yes when the controller echoes what it receives"}},
      {"max_line_length", IntField(&ControllerProfile::max_line_length,
                                   "longest line the controller accepts, without terminator")},
      {"decimals", IntField(&ControllerProfile::decimals, "decimals written for joint angles")},
      {"speed_template", StringField(&ControllerProfile::speed_template, "placeholders: {speed}")},
      {"move_template",
       StringField(&ControllerProfile::move_template, "stream mode move; placeholders {j1}..{j6}")},
      {"program_move_template", StringField(&ControllerProfile::program_move_template,
                                            "program step move; placeholders {j1}..{j6}")},
      {"drive_template",
       StringField(&ControllerProfile::drive_template, "placeholders {joint},{change},{speed}")},
      {"edit_template", StringField(&ControllerProfile::edit_template, "placeholder {name}")},
      {"end_edit_line", StringField(&ControllerProfile::end_edit_line, "leaves the editor")},
      {"execute_template", StringField(&ControllerProfile::execute_template, "placeholder {name}")},
      {"mode",
       {[](const std::string& v, ControllerProfile* p) {
          if (!ParseSendMode(v, &p->mode)) return "'" + v + "' is not stream or program";
          return std::string();
        },
        [](const ControllerProfile& p) { return std::string(SendModeName(p.mode)); },
        "stream (one DO MOVE per line) or program (EDIT ... E, then EXECUTE)"}},
      {"program_name",
       StringField(&ControllerProfile::program_name, "program name in program mode")},
      {"prompt_timeout_s", DoubleField(&ControllerProfile::prompt_timeout_s,
                                       "seconds to wait for a prompt after a line")},
      {"motion_timeout_s", DoubleField(&ControllerProfile::motion_timeout_s,
                                       "seconds to wait for a prompt after a motion line")},
      {"joint_speed_at_100_deg_s",
       {[](const std::string& v, ControllerProfile* p) {
          std::stringstream ss(v);
          std::string part;
          int j = 0;
          JointArray speeds{};
          while (std::getline(ss, part, ',')) {
            double d = 0;
            if (j >= kJoints || !ParseFiniteDouble(Trim(part), &d)) j = kJoints + 1;
            if (j < kJoints) speeds[j] = d;
            ++j;
          }
          if (j != kJoints) return "'" + v + "' is not six comma-separated speeds (deg/s)";
          p->joint_speed_at_100_deg_s = speeds;
          return std::string();
        },
        [](const ControllerProfile& p) {
          std::string s;
          for (int j = 0; j < kJoints; ++j) {
            if (j) s += ',';
            s += FormatExact(p.joint_speed_at_100_deg_s[j], 1);
          }
          return s;
        },
        "each joint's speed at SPEED 100, J1..J6, deg/s"}},
  };
  return fields;
}

}  // namespace

const char* SendModeName(SendMode mode) {
  return mode == SendMode::kProgram ? "program" : "stream";
}

bool ParseSendMode(const std::string& text, SendMode* out) {
  if (text == "stream") {
    *out = SendMode::kStream;
  } else if (text == "program") {
    *out = SendMode::kProgram;
  } else {
    return false;
  }
  return true;
}

Status ControllerProfile::Check() const {
  if (terminator.empty()) return Status::Error("terminator: must not be empty");
  for (char c : terminator) {
    if (c != '\r' && c != '\n') return Status::Error("terminator: only CR and LF are allowed");
  }
  if (prompt_top.empty()) return Status::Error("prompt_top: must not be empty");
  if (prompt_running.empty()) return Status::Error("prompt_running: must not be empty");
  if (error_prefix.empty()) return Status::Error("error_prefix: must not be empty");
  if (max_line_length < 20 || max_line_length > 1024) {
    return Status::Error("max_line_length: must be in 20..1024");
  }
  if (decimals < 0 || decimals > 4) return Status::Error("decimals: must be in 0..4");
  const std::vector<std::pair<std::string, const std::string*>> templates = {
      {"speed_template", &speed_template},
      {"move_template", &move_template},
      {"program_move_template", &program_move_template},
      {"drive_template", &drive_template},
      {"edit_template", &edit_template},
      {"execute_template", &execute_template}};
  for (const auto& [key, text] : templates) {
    const std::string err = CheckTemplate(key, *text);
    if (!err.empty()) return Status::Error(err);
  }
  if (end_edit_line.empty()) return Status::Error("end_edit_line: must not be empty");
  if (program_name.empty() || program_name.size() > 15) {
    return Status::Error("program_name: must be 1..15 characters");
  }
  for (char c : program_name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.') {
      return Status::Error("program_name: '" + program_name +
                           "' may only use letters, digits, '_' and '.'");
    }
  }
  if (!(prompt_timeout_s > 0)) return Status::Error("prompt_timeout_s: must be > 0");
  if (!(motion_timeout_s > 0)) return Status::Error("motion_timeout_s: must be > 0");
  for (int j = 0; j < kJoints; ++j) {
    if (!std::isfinite(joint_speed_at_100_deg_s[j]) || !(joint_speed_at_100_deg_s[j] > 0)) {
      return Status::Error("joint_speed_at_100_deg_s: J" + std::to_string(j + 1) + " must be > 0");
    }
  }
  return Status::Ok();
}

Status ParseProfile(std::istream& in, const std::string& source_name, ControllerProfile* out) {
  ControllerProfile p = ControllerProfile::Default();
  std::set<std::string> seen;
  std::string raw;
  int line_no = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    if (line_no == 1) StripUtf8Bom(&raw);
    const std::string where = source_name + ":" + std::to_string(line_no) + ": ";
    const std::string line = Trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const auto eq = line.find('=');
    if (eq == std::string::npos) {
      return Status::Error(where + "expected 'key = value', got '" + line + "'");
    }
    const std::string key = Trim(line.substr(0, eq));
    const std::string value = Trim(line.substr(eq + 1));
    const Field* field = nullptr;
    for (const auto& [name, f] : Fields()) {
      if (name == key) field = &f;
    }
    if (!field) return Status::Error(where + "unknown key '" + key + "'");
    if (!seen.insert(key).second) return Status::Error(where + "'" + key + "' given twice");
    const std::string err = field->set(value, &p);
    if (!err.empty()) return Status::Error(where + key + ": " + err);
  }
  if (in.bad()) return Status::Error(source_name + ": read error");
  const Status check = p.Check();
  if (!check.ok()) return Status::Error(source_name + ": " + check.message());
  *out = p;
  return Status::Ok();
}

Status ReadProfile(const std::string& path, ControllerProfile* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Error(path + ": cannot open the controller profile");
  return ParseProfile(in, path, out);
}

std::string FormatProfile(const ControllerProfile& profile) {
  std::string text = "# armmimic controller profile: key = value, '#' starts a comment.\n";
  for (const auto& [name, field] : Fields()) {
    text += "\n# " + std::string(field.doc) + "\n";
    text += name + " = " + field.get(profile) + "\n";
  }
  return text;
}

}  // namespace armmimic::robot
