// What a send needs besides the program, filled by the CLI from its flags and by the robot panel
// from its fields: the controller profile (built in or a file, with the timeout overrides), and
// whether an earlier send of the same program stopped before its end (its journal), so a shell
// can offer to resume it before asking how to start.
#pragma once

#include <string>

#include "armmimic/core/status.h"
#include "armmimic/robot/profile.h"
#include "armmimic/robot/send_session.h"
#include "armmimic/robot/val_program.h"

namespace armmimic::robot {

struct SendSettings {
  std::string profile_path;     // "": the built-in profile
  double prompt_timeout_s = 0;  // > 0: replaces the profile's prompt_timeout_s (--timeout)
  double motion_timeout_s = 0;  // > 0: replaces the profile's motion_timeout_s (--motion-timeout)
  // The ranges of the table's rows (option_tables.h, "send.*"): a timeout is >= 0.
  Status Check() const;
};

// The profile a send uses: the file's (errors name "file:line") or the built-in one, with the
// timeouts given. A negative timeout is an error keyed by its row (Check()).
Status LoadSendProfile(const SendSettings& settings, ControllerProfile* profile);

// How a send starts, from the shells' two switches (--resume, --restart; both is an error the
// shells refuse before).
SendStart StartFor(bool resume, bool restart);

// An earlier send of exactly these lines (the journal's identity) that has not finished.
struct UnfinishedSend {
  bool found = false;
  bool journal_exists = false;
  bool same_program = false;  // the journal records exactly these lines
  bool done = false;          // the journal records the send as finished
  int acknowledged = 0;       // lines the controller acknowledged
  int total = 0;              // lines in the program
  std::string journal_path;
};
// Reads INPUT.journal. A missing journal, a finished one or one for other lines: found = false.
// An unreadable journal is an error naming it.
Status FindUnfinishedSend(const ValProgram& program, const std::string& input, UnfinishedSend* out);

}  // namespace armmimic::robot
