// The line protocol with the controller as a transport-free state machine: lines out, echoes,
// prompts, error replies and time-outs in, fed bytes and time.
// Length: one state machine whose handlers share the state of the line in flight.
#include "armmimic/robot/link_protocol.h"
#include "armmimic/core/text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace armmimic::robot {
namespace {

// Drops control characters and bytes outside ASCII, turns tabs into blanks, trims.
std::string Clean(const std::string& raw) {
  std::string s;
  s.reserve(raw.size());
  for (char c : raw) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '\t') {
      s += ' ';
    } else if (u >= 0x20 && u < 0x7f) {
      s += c;
    }
  }
  std::size_t b = 0, e = s.size();
  while (b < e && s[b] == ' ') ++b;
  while (e > b && s[e - 1] == ' ') --e;
  return s.substr(b, e - b);
}

std::string FormatSeconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.1f", s);
  std::string out = buf;
  for (char& c : out) {
    if (c == ',') c = '.';
  }
  return out;
}

// "MOVE" matched by any non-empty prefix of `keyword`, at least `min_len` letters.
bool IsPrefixOf(const std::string& word, const std::string& keyword, std::size_t min_len) {
  return word.size() >= min_len && word.size() <= keyword.size() &&
         keyword.compare(0, word.size(), word) == 0;
}

// The instruction part of a line: "DO MOVE x" -> "MOVE x" (normalized).
std::string StripDo(const std::string& normalized, bool* had_do) {
  *had_do = normalized.rfind("DO ", 0) == 0;
  return *had_do ? normalized.substr(3) : normalized;
}

std::string FirstWord(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) ++i;
  return s.substr(0, i);
}

}  // namespace

LinkSettings LinkSettings::FromProfile(const ControllerProfile& profile) {
  LinkSettings s;
  s.terminator = profile.terminator;
  s.prompt_top = profile.prompt_top;
  s.prompt_running = profile.prompt_running;
  s.error_prefix = profile.error_prefix;
  s.echo = profile.echo;
  return s;
}

std::string NormalizeLine(const std::string& line) {
  std::string s;
  for (char c : line) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!s.empty() && s.back() != ' ') s += ' ';
    } else {
      s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
  }
  if (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

bool ParseWhereReply(const std::vector<std::string>& replies, JointArray* joints_deg) {
  for (auto it = replies.rbegin(); it != replies.rend(); ++it) {
    std::vector<double> values;
    std::string token;
    bool numbers_only = true;
    const std::string line = *it + " ";
    for (char c : line) {
      if (c == ' ' || c == ',' || c == '\t') {
        if (!token.empty()) {
          double v = 0;
          if (!ParseFiniteDouble(token, &v)) numbers_only = false;
          values.push_back(v);
          token.clear();
        }
      } else {
        token += c;
      }
    }
    if (numbers_only && values.size() == static_cast<std::size_t>(kJoints)) {
      for (int j = 0; j < kJoints; ++j) (*joints_deg)[j] = values[j];
      return true;
    }
  }
  return false;
}

bool ParsePpointTarget(const std::string& line, JointArray* joints_deg) {
  bool had_do = false;
  const std::string instr = StripDo(NormalizeLine(line), &had_do);
  if (!IsPrefixOf(FirstWord(instr), "MOVE", 1)) return false;
  const std::size_t open = instr.find("#PPOINT(");
  const std::size_t close = instr.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open) return false;
  const std::string args = instr.substr(open + 8, close - open - 8);
  std::vector<double> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = args.find(',', start);
    std::string t =
        args.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    while (!t.empty() && t.front() == ' ') t.erase(t.begin());
    while (!t.empty() && t.back() == ' ') t.pop_back();
    double v = 0;
    if (!ParseFiniteDouble(t, &v)) return false;
    values.push_back(v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (values.size() != static_cast<std::size_t>(kJoints)) return false;
  for (int j = 0; j < kJoints; ++j) (*joints_deg)[j] = values[j];
  return true;
}

bool IsMotionLine(const std::string& line) {
  bool had_do = false;
  const std::string instr = StripDo(NormalizeLine(line), &had_do);
  const std::string word = FirstWord(instr);
  if (IsPrefixOf(word, "MOVE", 1)) return true;
  if (had_do && IsPrefixOf(word, "DRIVE", 2)) return true;
  return !had_do && IsPrefixOf(word, "EXECUTE", 2);
}

LinkProtocol::LinkProtocol(LinkSettings settings) : settings_(std::move(settings)) {}

void LinkProtocol::Start(std::vector<LinkLine> lines, const std::string& source_name,
                         double now_s) {
  lines_ = std::move(lines);
  open_ended_ = false;
  source_name_ = source_name;
  next_ = 0;
  written_ = false;
  rx_.clear();
  out_ = settings_.terminator;
  state_ = LinkState::kWaking;
  error_ = LinkError::kNone;
  error_message_.clear();
  error_key_.clear();
  controller_text_.clear();
  wake_attempt_ = 1;
  now_s_ = now_s;
  last_rx_s_ = now_s;
  deadline_s_ = now_s + settings_.wake_timeout_s;
  noise_ = 0;
}

void LinkProtocol::StartStream(const std::string& source_name, double now_s) {
  Start({}, source_name, now_s);
  open_ended_ = true;
}

void LinkProtocol::Append(LinkLine line, double now_s) {
  if (finished()) return;
  lines_.push_back(std::move(line));
  now_s_ = std::max(now_s_, now_s);
  if (state_ == LinkState::kReady) SendNext(now_s_);
}

void LinkProtocol::EndStream() {
  open_ended_ = false;
  if (state_ == LinkState::kReady) state_ = LinkState::kDone;
}

std::string LinkProtocol::TakeOutput() {
  std::string out;
  out.swap(out_);
  return out;
}

const LinkLine* LinkProtocol::in_flight() const {
  return written_ && next_ < lines_.size() ? &lines_[next_] : nullptr;
}

void LinkProtocol::Abort(const std::string& message, const std::string& key) {
  if (finished()) return;
  Fail(LinkError::kAborted, message);
  error_key_ = key;
}

void LinkProtocol::OnBytes(std::string_view data, double now_s) {
  now_s_ = std::max(now_s_, now_s);
  if (finished()) return;
  last_rx_s_ = now_s_;
  rx_.append(data.data(), data.size());
  Scan(now_s_);
  // A controller line is at most a few hundred bytes: a longer run without a line end is noise.
  // Keep only its end (where a prompt would be), so scanning stays linear.
  constexpr std::size_t kMaxPending = 4096;
  if (rx_.size() > kMaxPending) {
    rx_.erase(0, rx_.size() - kMaxPending / 2);
    ++noise_;
  }
}

void LinkProtocol::OnTick(double now_s) {
  now_s_ = std::max(now_s_, now_s);
  if (finished()) return;
  Scan(now_s_);
  if (finished() || now_s_ < deadline_s_) return;
  if (state_ == LinkState::kWaking) {
    if (wake_attempt_ < settings_.wake_attempts) {
      ++wake_attempt_;
      out_ += settings_.terminator;
      deadline_s_ = now_s_ + settings_.wake_timeout_s;
      return;
    }
    Fail(LinkError::kNotReady,
         source_name_ + ": no prompt from the controller after " + std::to_string(wake_attempt_) +
             " carriage returns (" + FormatSeconds(wake_attempt_ * settings_.wake_timeout_s) +
             " s): check the cable, the baud rate and that the controller is at its monitor");
  } else if (state_ == LinkState::kWaitingReply) {
    const LinkLine& line = lines_[next_];
    std::string why = settings_.echo && !echo_seen_ ? "its echo never came back"
                                                    : "its echo came back but no prompt";
    if (running_seen_) why = "the program started but did not finish";
    Fail(LinkError::kTimeout, Where() + ": no prompt from the controller within " +
                                  FormatSeconds(line.timeout_s) + " s after '" + line.text + "' (" +
                                  why + ")");
  }
}

std::string LinkProtocol::Where() const {
  const int line_no = next_ < lines_.size() ? lines_[next_].line_no : 0;
  return source_name_ + ":" + std::to_string(line_no);
}

void LinkProtocol::Fail(LinkError error, const std::string& message) {
  state_ = LinkState::kFailed;
  error_ = error;
  error_message_ = message;
}

bool LinkProtocol::IsTopPrompt(const std::string& s) const { return s == settings_.prompt_top; }

bool LinkProtocol::IsEditPrompt(const std::string& s) const {
  // The program editor's "12?" line-number prompt.
  if (s.empty() || s.back() != '?') return false;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(s[i])) && s[i] != ' ') return false;
  }
  return true;
}

bool LinkProtocol::IsError(const std::string& s) const {
  const std::string& p = settings_.error_prefix;
  return !p.empty() && s.size() > p.size() && s.compare(0, p.size(), p) == 0 &&
         s != settings_.prompt_running;
}

bool LinkProtocol::EchoMatches(const std::string& s, std::string* rest) const {
  const std::string want = NormalizeLine(lines_[next_].text);
  std::string got = NormalizeLine(s);
  rest->clear();
  // A prompt the controller printed again before the echo: ".DO MOVE ...".
  for (const std::string& p : {settings_.prompt_top, settings_.prompt_running}) {
    if (!p.empty() && got.size() > p.size() && got.compare(0, p.size(), p) == 0 &&
        NormalizeLine(got.substr(p.size())).rfind(want, 0) == 0) {
      got = NormalizeLine(got.substr(p.size()));
      break;
    }
  }
  if (got == want) return true;
  if (want.empty() || got.rfind(want, 0) != 0) return false;
  // Something glued after the echo: a prompt or an error ("DO MOVE ... .").
  *rest = NormalizeLine(got.substr(want.size()));
  return IsTopPrompt(*rest) || IsEditPrompt(*rest) || IsError(*rest);
}

void LinkProtocol::Scan(double now_s) {
  while (!finished()) {
    const std::size_t p = rx_.find_first_of("\r\n");
    if (p == std::string::npos) break;
    const std::string segment = rx_.substr(0, p);
    rx_.erase(0, p + 1);
    const std::string cleaned = Clean(segment);
    // Bytes outside printable ASCII mark a garbled line: never taken as a reply.
    dirty_ = cleaned.size() != segment.size() &&
             segment.find_first_not_of(" \t") != std::string::npos &&
             std::any_of(segment.begin(), segment.end(), [](char c) {
               const unsigned char u = static_cast<unsigned char>(c);
               return (u < 0x20 && c != '\t') || u >= 0x7f;
             });
    HandleLine(cleaned);
    if (pending_prompt_) {
      pending_prompt_ = false;
      OnPrompt(now_s);
    }
  }
  if (!finished() && !rx_.empty()) {
    const std::string tail = Clean(rx_);
    if (tail.empty() || HandleTail(tail, now_s)) rx_.clear();
  }
}

void LinkProtocol::HandleLine(const std::string& s) {
  if (s.empty()) return;
  if (state_ == LinkState::kWaking) {
    if (IsTopPrompt(s)) {
      pending_prompt_ = true;
    } else if (s == settings_.prompt_running) {
      Fail(LinkError::kNotReady, source_name_ + ": the controller is running a program (prompt '" +
                                     settings_.prompt_running +
                                     "'): stop it (ABORT) or let it end, then send again");
    } else {
      ++noise_;
    }
    return;
  }
  if (state_ != LinkState::kWaitingReply) return;
  const LinkLine& line = lines_[next_];
  if (settings_.echo && !echo_seen_) {
    std::string rest;
    if (EchoMatches(s, &rest)) {
      echo_seen_ = true;
      if (IsError(rest)) {
        controller_text_ = rest;
        Fail(LinkError::kControllerError,
             Where() + ": the controller refused '" + line.text + "': " + rest);
      } else if (!rest.empty()) {
        pending_prompt_ = true;
      }
      return;
    }
    if (IsError(s)) {
      controller_text_ = s;
      Fail(LinkError::kControllerError,
           Where() + ": the controller refused '" + line.text + "': " + s);
      return;
    }
    ++noise_;  // a stale prompt from the wake-up, or noise on the line
    return;
  }
  if (IsError(s)) {
    controller_text_ = s;
    Fail(LinkError::kControllerError,
         Where() + ": the controller refused '" + line.text + "': " + s);
  } else if (IsTopPrompt(s) || IsEditPrompt(s)) {
    pending_prompt_ = true;
  } else if (s == settings_.prompt_running) {
    running_seen_ = true;
  } else if (dirty_) {
    ++noise_;
  } else {
    replies_.push_back(s);
  }
}

bool LinkProtocol::HandleTail(const std::string& s, double now_s) {
  const bool settled = now_s - last_rx_s_ >= settings_.prompt_settle_s;
  if (state_ == LinkState::kWaking) {
    if (IsTopPrompt(s)) {
      OnPrompt(now_s);
      return true;
    }
    if (s == settings_.prompt_running && settled) {
      HandleLine(s);
      return true;
    }
    return false;
  }
  if (state_ != LinkState::kWaitingReply) return false;
  if (settings_.echo && !echo_seen_) {
    std::string rest;
    if (EchoMatches(s, &rest) && (IsTopPrompt(rest) || IsEditPrompt(rest))) {
      echo_seen_ = true;
      OnPrompt(now_s);
      return true;
    }
    return false;
  }
  if (IsTopPrompt(s) || IsEditPrompt(s)) {
    OnPrompt(now_s);
    return true;
  }
  if (s == settings_.prompt_running && settled) {
    running_seen_ = true;
    return true;
  }
  return false;
}

void LinkProtocol::OnPrompt(double now_s) {
  if (state_ == LinkState::kWaking) {
    SendNext(now_s);
    return;
  }
  if (state_ != LinkState::kWaitingReply) return;
  last_replies_ = replies_;
  const LinkLine& line = lines_[next_];
  written_ = false;
  ++next_;
  if (on_ack_) on_ack_(line, last_replies_);
  if (finished()) return;  // the callback stopped the stream
  SendNext(now_s);
}

void LinkProtocol::SendNext(double now_s) {
  if (next_ >= lines_.size()) {
    state_ = open_ended_ ? LinkState::kReady : LinkState::kDone;
    return;
  }
  const LinkLine& line = lines_[next_];
  if (gate_) {
    const std::string why = gate_(line);
    if (!why.empty()) {
      Fail(LinkError::kRefused, Where() + ": not sent: " + why);
      return;
    }
  }
  if (on_sent_) on_sent_(line);
  if (finished()) return;  // the callback stopped the stream: nothing is written
  out_ += line.text + settings_.terminator;
  written_ = true;
  echo_seen_ = false;
  running_seen_ = false;
  replies_.clear();
  deadline_s_ = now_s + line.timeout_s;
  state_ = LinkState::kWaitingReply;
}

}  // namespace armmimic::robot
