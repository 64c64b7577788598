// The PUMA 760 controller emulator: the VAL subset it interprets, the joint state and the
// timing of motions, fed bytes and time like a serial line.
// Length: one interpreter whose commands share the controller's state and output.
#include "armmimic/sim/puma_emulator.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "armmimic/core/angle_file.h"

namespace armmimic::sim {
namespace {

std::string Trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

std::string Upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Splits "WORD rest" into the leading word (letters only) and the trimmed rest.
void SplitWord(const std::string& line, std::string* word, std::string* rest) {
  std::size_t i = 0;
  while (i < line.size() && std::isalpha(static_cast<unsigned char>(line[i]))) ++i;
  *word = line.substr(0, i);
  *rest = Trim(line.substr(i));
}

// VAL's unique-prefix rule. Returns the matched keyword, "" when none, "?" when ambiguous.
std::string MatchKeyword(const std::string& word, const std::vector<std::string>& keywords) {
  if (word.empty()) return "";
  std::string found;
  for (const std::string& k : keywords) {
    if (k == word) return k;
    if (k.compare(0, word.size(), word) == 0) {
      if (!found.empty()) return "?";
      found = k;
    }
  }
  return found;
}

bool ParseNumber(const std::string& text, double* out) {
  const std::string t = Trim(text);
  if (t.empty()) return false;
  const char* b = t.data();
  if (*b == '+') ++b;
  const char* e = t.data() + t.size();
  auto [p, ec] = std::from_chars(b, e, *out);
  return ec == std::errc() && p == e && std::isfinite(*out);
}

bool ParseNumberList(const std::string& text, std::vector<double>* out) {
  out->clear();
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    double v = 0;
    if (!ParseNumber(
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start),
            &v)) {
      return false;
    }
    out->push_back(v);
    if (comma == std::string::npos) return true;
    start = comma + 1;
  }
}

const std::vector<std::string> kCommands = {"ABORT", "DO",    "EDIT", "EXECUTE",
                                            "HERE",  "SPEED", "WHERE"};
const std::vector<std::string> kInstructions = {"DELAY", "DRIVE", "MOVE", "SPEED"};

}  // namespace

PumaEmulator::PumaEmulator(EmulatorOptions options)
    : options_(std::move(options)), current_(options_.start_deg), target_(options_.start_deg) {}

std::string PumaEmulator::FormatJoints(const robot::JointArray& deg) {
  std::string s;
  for (double d : deg) {
    const std::string v = FormatNumber(d, 3);
    s += std::string(v.size() < 10 ? 10 - v.size() : 1, ' ') + v;
  }
  return s;
}

bool PumaEmulator::busy() const {
  return motion_.active || mode_ == Mode::kRunning || delay_until_s_ > now_s_;
}

double PumaEmulator::NextEventTime() const {
  if (motion_.active) return motion_.end_s;
  if (delay_until_s_ > now_s_) return delay_until_s_;
  return -1;
}

void PumaEmulator::Emit(const std::string& text) {
  if (silenced_) return;
  out_ += text;
  out_ += options_.newline;
}

void PumaEmulator::Prompt() {
  if (silenced_) return;
  if (options_.garble_after >= 0 && lines_received_ > options_.garble_after) {
    out_ += "~\x01#}\x7f@\xfe!";
    out_ += options_.newline;
  }
  switch (mode_) {
    case Mode::kTop:
      out_ += ".";
      break;
    case Mode::kEdit:
      out_ += std::to_string(programs_[edit_name_].size() + 1) + "? ";
      break;
    case Mode::kRunning:
      out_ += "*";
      break;
  }
}

void PumaEmulator::Advance(double now_s) {
  now_s_ = std::max(now_s_, now_s);
  if (!motion_.active) return;
  if (now_s_ >= motion_.end_s) {
    current_ = motion_.to;
    motion_.active = false;
    return;
  }
  const double span = motion_.end_s - motion_.start_s;
  const double f = span > 0 ? (now_s_ - motion_.start_s) / span : 1.0;
  for (int j = 0; j < robot::kJoints; ++j) {
    current_[j] = motion_.from[j] + f * (motion_.to[j] - motion_.from[j]);
  }
}

std::string PumaEmulator::Tick(double now_s) {
  Advance(now_s);
  if (awaiting_prompt_ && !motion_.active) {
    awaiting_prompt_ = false;
    Prompt();
  }
  if (mode_ == Mode::kRunning) StepProgram(now_s_);
  ProcessLines(now_s_);
  std::string out;
  out.swap(out_);
  return out;
}

std::string PumaEmulator::Feed(std::string_view bytes, double now_s) {
  Advance(now_s);
  for (char c : bytes) {
    if (c == '\n' && last_was_cr_) {
      last_was_cr_ = false;
      continue;
    }
    last_was_cr_ = (c == '\r');
    if (c == '\r' || c == '\n') {
      queue_.push_back(input_);
      input_.clear();
    } else if (static_cast<unsigned char>(c) >= 0x20 || c == '\t') {
      // A line far beyond the limit is still read to its end; only its length matters then.
      if (input_.size() < 4096) input_ += c;
    }
  }
  return Tick(now_s);
}

void PumaEmulator::OnDisconnect() {
  input_.clear();
  queue_.clear();
  last_was_cr_ = false;
  silenced_ = false;
}

void PumaEmulator::ProcessLines(double now_s) {
  while (!queue_.empty() && !awaiting_prompt_) {
    const std::string line = queue_.front();
    queue_.erase(queue_.begin());
    ExecuteLine(line, now_s);
  }
}

void PumaEmulator::ExecuteLine(const std::string& raw, double now_s) {
  const std::string line = Upper(Trim(raw));
  if (line.empty()) {
    if (!silenced_) out_ += options_.newline;
    Prompt();
    return;
  }
  const int n = ++lines_received_;
  source_ = Trim(raw);
  if (options_.silent_after >= 0 && !silence_done_ && n == options_.silent_after + 1) {
    silence_done_ = true;
    silenced_ = true;
  }
  Emit(raw);  // the echo
  if (static_cast<int>(raw.size()) > options_.max_line_length) {
    Emit("*Line too long*");
    Prompt();
    return;
  }
  if (options_.fail_after >= 0 && !fail_done_ && n == options_.fail_after + 1) {
    fail_done_ = true;
    Emit("*Servo error*");
    Prompt();
    return;
  }
  if (mode_ == Mode::kEdit) {
    if (line == "E" || line == "EXIT") {
      mode_ = Mode::kTop;
      Prompt();
      return;
    }
    const std::string err = Instruction(line, now_s);
    if (!err.empty()) {
      Emit(err);
    } else {
      programs_[edit_name_].push_back(line);
    }
    Prompt();
    return;
  }
  if (mode_ == Mode::kRunning) {
    std::string word, rest;
    SplitWord(line, &word, &rest);
    const std::string cmd = MatchKeyword(word, kCommands);
    if (cmd == "ABORT") {
      Advance(now_s);
      motion_.active = false;
      target_ = current_;
      delay_until_s_ = -1;
      mode_ = Mode::kTop;
      Emit("PROGRAM ABORTED: " + run_name_);
    } else if (cmd == "WHERE") {
      Emit("     JT1       JT2       JT3       JT4       JT5       JT6");
      Emit(FormatJoints(current_));
    } else {
      Emit("*Program already running*");
    }
    Prompt();
    return;
  }
  TopLevel(line, now_s);
}

void PumaEmulator::TopLevel(const std::string& line, double now_s) {
  std::string word, rest;
  SplitWord(line, &word, &rest);
  const std::string cmd = MatchKeyword(word, kCommands);
  if (cmd.empty()) {
    Emit("*Unknown command*");
  } else if (cmd == "?") {
    Emit("*Ambiguous command*");
  } else if (cmd == "SPEED") {
    double v = 0;
    if (!ParseNumber(rest, &v)) {
      Emit("*Invalid argument*");
    } else if (v <= 0 || v > 100) {
      Emit("*Value out of range*");
    } else {
      monitor_speed_ = v;
    }
  } else if (cmd == "DO") {
    const std::string err = Instruction(rest, now_s);
    if (!err.empty()) {
      Emit(err);
    } else if (motion_.active || delay_until_s_ > now_s) {
      awaiting_prompt_ = true;  // the prompt comes when the motion ends
      if (!motion_.active) motion_ = Motion{true, current_, current_, now_s, delay_until_s_};
      return;
    }
  } else if (cmd == "HERE") {
    if (rest.empty()) {
      Emit(FormatJoints(current_));
    } else {
      std::string name = rest[0] == '#' ? rest.substr(1) : rest;
      points_[name] = current_;
    }
  } else if (cmd == "WHERE") {
    Emit("     JT1       JT2       JT3       JT4       JT5       JT6");
    Emit(FormatJoints(current_));
  } else if (cmd == "EDIT") {
    if (rest.empty() || !std::isalpha(static_cast<unsigned char>(rest[0]))) {
      Emit("*Invalid program name*");
    } else {
      edit_name_ = rest;
      programs_[edit_name_].clear();
      mode_ = Mode::kEdit;
    }
  } else if (cmd == "EXECUTE") {
    std::string name = rest.substr(0, rest.find(','));
    name = Trim(name);
    if (programs_.count(name) == 0) {
      Emit("*Undefined program*");
    } else {
      mode_ = Mode::kRunning;
      run_name_ = name;
      run_pc_ = 0;
      program_speed_ = 100;
      Prompt();
      StepProgram(now_s);
      return;
    }
  } else if (cmd == "ABORT") {
    // Nothing runs: nothing to do.
  }
  Prompt();
}

std::string PumaEmulator::Instruction(const std::string& text, double now_s) {
  const bool execute = mode_ != Mode::kEdit;
  std::string word, rest;
  SplitWord(text, &word, &rest);
  const std::string instr = MatchKeyword(word, kInstructions);
  if (instr.empty()) return "*Unknown instruction*";
  if (instr == "?") return "*Ambiguous instruction*";
  if (instr == "SPEED") {
    double v = 0;
    if (!ParseNumber(rest, &v)) return "*Invalid argument*";
    if (v <= 0 || v > 100) return "*Value out of range*";
    if (execute) program_speed_ = v;
    return "";
  }
  if (instr == "DELAY") {
    double v = 0;
    if (!ParseNumber(rest, &v) || v < 0) return "*Invalid argument*";
    if (execute) delay_until_s_ = now_s + v * options_.time_scale;
    return "";
  }
  robot::JointArray to = current_;
  double speed = program_speed_;
  if (instr == "MOVE") {
    if (rest.empty() || rest[0] != '#') return "*Invalid argument*";
    const std::string loc = rest.substr(1);
    const std::size_t open = loc.find('(');
    if (open != std::string::npos) {
      if (Trim(loc.substr(0, open)) != "PPOINT" || loc.back() != ')') return "*Syntax error*";
      std::vector<double> v;
      if (!ParseNumberList(loc.substr(open + 1, loc.size() - open - 2), &v) ||
          v.size() != robot::kJoints) {
        return "*Syntax error*";
      }
      std::copy(v.begin(), v.end(), to.begin());
    } else if (execute) {
      auto it = points_.find(Trim(loc));
      if (it == points_.end()) return "*Undefined location*";
      to = it->second;
    }
  } else {  // DRIVE joint,change,speed
    std::vector<double> v;
    if (!ParseNumberList(rest, &v) || v.size() != 3) return "*Syntax error*";
    if (v[0] != std::floor(v[0]) || v[0] < 1 || v[0] > robot::kJoints) return "*Invalid joint*";
    if (v[2] <= 0 || v[2] > 100) return "*Value out of range*";
    to[static_cast<int>(v[0]) - 1] += v[1];
    speed = v[2];
  }
  if (!execute) return "";
  for (int j = 0; j < robot::kJoints; ++j) {
    if (!options_.limits.Inside(j, to[j])) {
      return "*Joint " + std::to_string(j + 1) + " out of range*";
    }
  }
  return StartMotion(to, speed, source_, now_s);
}

std::string PumaEmulator::StartMotion(const robot::JointArray& to, double speed_pct,
                                      const std::string& source, double now_s) {
  const double fraction = (monitor_speed_ / 100.0) * (speed_pct / 100.0);
  double longest_s = 0;
  for (int j = 0; j < robot::kJoints; ++j) {
    const double rate = options_.joint_speed_at_100_deg_s[j] * fraction;
    longest_s = std::max(longest_s, std::abs(to[j] - current_[j]) / rate);
  }
  const double duration_s = (longest_s + options_.settle_s) * options_.time_scale;
  motion_ = Motion{true, current_, to, now_s, now_s + duration_s};
  target_ = to;
  LoggedMove move;
  move.seq = static_cast<int>(log_.size()) + 1;
  move.source = source;
  move.target_deg = to;
  move.start_s = now_s;
  move.end_s = now_s + duration_s;
  log_.push_back(move);
  if (on_move_) on_move_(move);
  if (duration_s <= 0) Advance(now_s);
  return "";
}

void PumaEmulator::StepProgram(double now_s) {
  while (mode_ == Mode::kRunning && !motion_.active && delay_until_s_ <= now_s) {
    const std::vector<std::string>& program = programs_[run_name_];
    if (run_pc_ >= program.size()) {
      mode_ = Mode::kTop;
      Emit("");
      Emit("PROGRAM COMPLETED: " + run_name_);
      Prompt();
      return;
    }
    const std::string instr = program[run_pc_++];
    source_ = run_name_ + " step " + std::to_string(run_pc_) + ": " + instr;
    const std::string err = Instruction(instr, now_s);
    if (!err.empty()) {
      mode_ = Mode::kTop;
      Emit("");
      Emit(err);
      Emit("PROGRAM HALTED: " + run_name_ + " step " + std::to_string(run_pc_));
      Prompt();
      return;
    }
  }
}

}  // namespace armmimic::sim
