// The questions the robot panel asks before a send moves the arm: the confirmation, which shows
// what robot::SummarizeSend found (lines, duration, start pose, each joint's range against its
// limits), and, when the journal shows an earlier send of the same program stopped part way,
// whether to resume it or start over.
#pragma once

#include <QString>

#include "armmimic/robot/send_setup.h"
#include "armmimic/robot/send_summary.h"

class QWidget;

namespace armmimic::gui {

// The confirmation's headline and its details (plain text, shown in a fixed-width font).
QString SendQuestion(const robot::SendSummary& summary, const QString& device);
QString SendDetails(const robot::SendSummary& summary);
// True only when the operator clicks "Move the robot": Esc, Cancel or closing do not move it.
bool ConfirmSend(QWidget* parent, const robot::SendSummary& summary, const QString& device);

// Whether a send may replace the different plan already in `path` (and so start its journal
// over). True only for "Replace".
bool AskReplacePlan(QWidget* parent, const QString& path);

enum class UnfinishedChoice { kResume, kStartOver, kCancel };
UnfinishedChoice AskAboutUnfinished(QWidget* parent, const robot::UnfinishedSend& unfinished,
                                    const QString& program);

}  // namespace armmimic::gui
