#include "armmimic/robot/send_setup.h"

#include "armmimic/robot/journal.h"
#include "armmimic/robot/option_tables.h"

namespace armmimic::robot {

Status SendSettings::Check() const { return CheckOptionFields(SendOptionFields(), "send", *this); }

Status LoadSendProfile(const SendSettings& settings, ControllerProfile* profile) {
  *profile = ControllerProfile::Default();
  if (!settings.profile_path.empty()) {
    const Status s = ReadProfile(settings.profile_path, profile);
    if (!s.ok()) return s;
  }
  if (const Status s = settings.Check(); !s.ok()) return s;
  if (settings.prompt_timeout_s > 0) profile->prompt_timeout_s = settings.prompt_timeout_s;
  if (settings.motion_timeout_s > 0) profile->motion_timeout_s = settings.motion_timeout_s;
  return Status::Ok();
}

SendStart StartFor(bool resume, bool restart) {
  SendStart start;
  start.mode = resume    ? SendStart::Mode::kResume
               : restart ? SendStart::Mode::kRestart
                         : SendStart::Mode::kFresh;
  return start;
}

Status FindUnfinishedSend(const ValProgram& program, const std::string& input,
                          UnfinishedSend* out) {
  *out = UnfinishedSend();
  out->journal_path = SendJournal::PathFor(input);
  out->total = static_cast<int>(program.lines.size());
  JournalState journal;
  const Status s = SendJournal::Read(out->journal_path, &journal);
  if (!s.ok()) return s;
  std::vector<std::string> texts;
  for (const ValLine& l : program.lines) texts.push_back(l.text);
  out->journal_exists = journal.exists;
  out->same_program = journal.exists && journal.hash == SendJournal::Hash(texts);
  out->done = journal.done;
  // The condition under which SendSession::Prepare refuses a fresh start.
  out->found = out->same_program && !journal.done && journal.sent > 0;
  out->acknowledged = journal.acknowledged;
  return Status::Ok();
}

}  // namespace armmimic::robot
