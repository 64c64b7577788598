#include "session_inputs.h"

namespace armmimic::gui {

std::vector<NamedPath> SessionInputs(const QStringList& opened, const AnalysisOptions& options) {
  std::vector<NamedPath> inputs;
  for (const QString& path : opened) inputs.push_back({"the open input", path.toStdString()});
  if (!options.background_path.empty()) {
    inputs.push_back({"the background image", options.background_path});
  }
  if (!options.arm_length_path.empty()) {
    inputs.push_back({"the arm-length image", options.arm_length_path});
  }
  if (!options.reference_path.empty()) {
    inputs.push_back({"the reference image", options.reference_path});
  }
  return inputs;
}

QString SameFileRefusal(const std::vector<NamedPath>& inputs, const QString& what,
                        const QString& path) {
  const Status st = CheckOutputsAreNotInputs(inputs, {{what.toStdString(), path.toStdString()}});
  return st ? QString() : QString::fromStdString(st.message());
}

}  // namespace armmimic::gui
