// Fuzzes the controller-reply side of the link state machine: a fixed program is streamed while
// the fuzzer plays the controller (arbitrary bytes, split anywhere, with arbitrary time steps).
// Properties:
//  - every line written is at most the profile's max line length, and the lines written are
//    exactly the program's lines, in order, each once (besides the bare wake-up terminators);
//  - a line is acknowledged only after it was written, in order, and (with echo on) only after
//    its text came back in the received bytes;
//  - a line the gate refuses is never written;
//  - once the input ends, time passing always brings it to Done or Failed, with a message on
//    failure and every line acknowledged on success.
#include "fuzz_input.h"

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "armmimic/robot/link_protocol.h"
#include "armmimic/robot/profile.h"

namespace {

using armmimic::robot::LinkLine;
using armmimic::robot::LinkProtocol;
using armmimic::robot::LinkState;

constexpr std::size_t kMaxLineLength = 80;

// Upper-case, without blanks, control characters and bytes outside ASCII: what survives of an
// echo whatever noise or line breaking surrounds it.
std::string Squash(const std::string& s) {
  std::string out;
  for (char c : s) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u > 0x20 && u < 0x7f) out += static_cast<char>(std::toupper(u));
  }
  return out;
}

struct Observer {
  std::vector<LinkLine> program;
  std::vector<int> sent;        // indices, in the order on_sent fired
  std::vector<int> acked;       // indices, in the order on_ack fired
  std::string rx_all;           // every byte received
  std::size_t chunk_start = 0;  // where the chunk being handled begins in rx_all
  std::size_t sent_at = 0;      // rx_all offset from which the line in flight's echo may come
  bool echo = true;
  int refused_index = -1;
  std::string written;  // every byte taken from TakeOutput
};

void CheckOutput(Observer& o, const std::string& out, const std::string& terminator) {
  o.written += out;
  // Split what was written into lines at the terminator.
  std::size_t pos = 0;
  while (pos < out.size()) {
    const std::size_t end = out.find(terminator, pos);
    if (end == std::string::npos) std::abort();  // every write ends with the terminator
    const std::string line = out.substr(pos, end - pos);
    if (line.size() > kMaxLineLength) std::abort();
    pos = end + terminator.size();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  armmimic::fuzz::FuzzInput fdp(data, size);
  armmimic::robot::ControllerProfile profile;
  const uint8_t flags = fdp.Byte();
  profile.echo = (flags & 1) == 0;
  if (flags & 2) profile.terminator = "\r\n";
  armmimic::robot::LinkSettings settings = armmimic::robot::LinkSettings::FromProfile(profile);

  Observer o;
  o.echo = profile.echo;
  const char* const texts[] = {
      "SPEED 50",     "DO MOVE #PPOINT(0.00,-90.00,0.00,0.00,0.00,0.00)", "DO DRIVE 2,10.00,50",
      "EDIT MIMIC",   "MOVE #PPOINT(1.00,-80.00,5.00,0.00,0.00,0.00)",    "E",
      "EXECUTE MIMIC"};
  const int n = 1 + (flags >> 2) % 7;
  for (int i = 0; i < n; ++i) {
    LinkLine l;
    l.text = texts[i];
    l.line_no = 3 + 2 * i;
    l.index = i;
    l.timeout_s = i == 1 ? 60 : 5;
    o.program.push_back(l);
  }
  if (flags & 0x80) o.refused_index = (flags >> 4) % n;

  LinkProtocol link(settings);
  link.SetGate([&o](const LinkLine& l) -> std::string {
    return l.index == o.refused_index ? "refused by the fuzz gate" : "";
  });
  link.SetSentCallback([&o](const LinkLine& l) {
    if (l.index == o.refused_index) std::abort();
    if (l.index != static_cast<int>(o.sent.size())) std::abort();  // in order, each once
    if (o.acked.size() != o.sent.size()) std::abort();  // the previous one was acknowledged
    o.sent.push_back(l.index);
    // The line may go out in the middle of a chunk (after a prompt in it): its echo can be in
    // the rest of that chunk, which the harness cannot place more precisely.
    o.sent_at = o.chunk_start;
  });
  link.SetAckCallback([&o](const LinkLine& l, const std::vector<std::string>&) {
    if (o.sent.empty() || o.sent.back() != l.index) std::abort();  // only the line in flight
    if (l.index != static_cast<int>(o.acked.size())) std::abort();
    if (o.echo && Squash(o.rx_all.substr(o.sent_at)).find(Squash(l.text)) == std::string::npos) {
      std::abort();  // acknowledged without its echo
    }
    o.acked.push_back(l.index);
  });

  double now = 0;
  link.Start(o.program, "fuzz.val", now);
  std::size_t last_ack = 0;
  while (!fdp.empty()) {
    const uint8_t op = fdp.Byte();
    switch (op % 4) {
      case 0:
      case 1: {
        const std::string bytes = fdp.Chunk(96);
        o.chunk_start = o.rx_all.size();
        o.rx_all += bytes;
        link.OnBytes(bytes, now);
        break;
      }
      case 2:
        now += (op >> 2) * 0.05;
        o.chunk_start = o.rx_all.size();
        link.OnTick(now);
        break;
      default:
        CheckOutput(o, link.TakeOutput(), settings.terminator);
        break;
    }
    if (link.acknowledged() < last_ack || link.acknowledged() > o.sent.size()) std::abort();
    last_ack = link.acknowledged();
    if (link.acknowledged() != o.acked.size()) std::abort();
    const LinkLine* flight = link.in_flight();
    if (flight && (o.sent.empty() || flight->index != o.sent.back())) std::abort();
  }
  // The controller falls silent: time alone must end the stream.
  o.chunk_start = o.rx_all.size();
  for (int i = 0; i < 16 && !link.finished(); ++i) {
    now += 100;
    link.OnTick(now);
  }
  CheckOutput(o, link.TakeOutput(), settings.terminator);
  if (!link.finished()) std::abort();
  if (link.state() == LinkState::kDone) {
    if (link.acknowledged() != link.total() || o.acked.size() != o.program.size()) std::abort();
    if (link.error() != armmimic::robot::LinkError::kNone) std::abort();
  } else {
    if (link.state() != LinkState::kFailed) std::abort();
    if (link.error() == armmimic::robot::LinkError::kNone) std::abort();
    if (link.error_message().rfind("fuzz.val", 0) != 0) std::abort();  // names the file
  }
  if (o.refused_index >= 0 && link.state() == LinkState::kDone) std::abort();
  // What was written: wake-up terminators, then each sent line once, in order.
  std::string expect_lines;
  for (int i : o.sent) expect_lines += o.program[i].text + settings.terminator;
  std::string written = o.written;
  while (written.rfind(settings.terminator, 0) == 0) written.erase(0, settings.terminator.size());
  std::string rest = written;
  // Wake-up terminators may also come only before the first line; strip them all from the front
  // and compare the remainder exactly.
  if (rest != expect_lines) std::abort();
  return 0;
}
