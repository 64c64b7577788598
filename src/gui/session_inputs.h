// The same-file rule in the application: the files the session reads (the open video or images
// and the analysis' background, arm-length and reference images) are never an export's target.
#pragma once

#include <QString>
#include <QStringList>
#include <vector>

#include "armmimic/core/same_file.h"
#include "armmimic/engines/analysis.h"

namespace armmimic::gui {

// The open inputs and the images `options` names, each with what it is for the message.
std::vector<NamedPath> SessionInputs(const QStringList& opened, const AnalysisOptions& options);

// The message refusing to write `path` (described as `what`, e.g. "the angle file") when it is
// the same file as one of `inputs`; empty when it may be written.
QString SameFileRefusal(const std::vector<NamedPath>& inputs, const QString& what,
                        const QString& path);

}  // namespace armmimic::gui
