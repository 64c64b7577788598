// EngineSettingsPanel's side of typed errors: the library keys an error by its setting
// (Status::key()); the panel finds that setting's field, frames it and names it by its label.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QToolButton>

#include "engine_settings_panel.h"
#include "field_error.h"
#include "parameter_form.h"

namespace armmimic::gui {

QWidget* EngineSettingsPanel::fieldForKey(const QString& key) const {
  const std::pair<const char*, QWidget*> inputs[] = {
      {"analysis.background", background_},         {"analysis.background_frames", bg_frames_},
      {"bgsub.background_frames", bg_frames_},      {"analysis.arm_length", arm_length_},
      {"analysis.reference", reference_},           {"analysis.start", start_},
      {"analysis.shoulder", shoulder_box_},         {"analysis.elbow", elbow_wrist_box_},
      {"analysis.wrist", elbow_wrist_box_},         {"analysis.roi", roi_box_},
      {"analysis.auto_calibrate", auto_calibrate_}, {"analysis.engine", engine_},
  };
  for (const auto& [name, field] : inputs) {
    if (key == name) return field;
  }
  const qsizetype dot = key.indexOf('.');
  if (dot < 0) return nullptr;
  EngineKind kind;
  if (!ParseEngineKind(key.left(dot).toStdString(), &kind)) return nullptr;
  return parameterEditor(kind, key.mid(dot + 1));
}

QString EngineSettingsPanel::showError(const QString& key, const QString& message) {
  QWidget* field = fieldForKey(key);
  if (!field) return message;
  const qsizetype dot = key.indexOf('.');
  EngineKind kind;
  if (ParseEngineKind(key.left(dot).toStdString(), &kind)) {
    // An engine parameter: its engine's page (the hybrid's shows lk's and bgsub's too), and the
    // Advanced section when it is there.
    const bool on_hybrid_page = engine_->currentData().toInt() == int(EngineKind::kHybrid) &&
                                (kind == EngineKind::kLk || kind == EngineKind::kBgsub);
    if (!on_hybrid_page) engine_->setCurrentIndex(engine_->findData(int(kind)));
    if (!field->isVisibleTo(forms_[int(kind)])) advancedToggle(kind)->setChecked(true);
  }
  // The background's image or frames: the mode that shows the field.
  if (field == background_ || field == bg_frames_) {
    const int mode = field == background_ ? 0 : 1;
    if (bg_mode_->currentIndex() == 2 || !field->isEnabled()) bg_mode_->setCurrentIndex(mode);
  }
  MarkFieldError(field);
  return FieldLabel(field) + ": " + message;
}

}  // namespace armmimic::gui
