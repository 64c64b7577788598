// EngineSettingsPanel: the engine choice, its parameters and the analysis inputs, edited in the
// same AnalysisOptions/EngineOptions structs the CLI fills from its flags. The parameter forms
// (the main ones and a collapsible "Advanced" section per engine) and their saved settings are
// built from the engines' parameter tables (armmimic/engines/option_fields.h), so every option
// is editable. The hybrid engine's page shows its own form with lk's and bgsub's below it (the
// same editors, moved there while it is chosen: engine_settings_pages.cpp).
#pragma once

#include <QWidget>

#include "armmimic/engines/analysis.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLineEdit;
class QPushButton;
class QSettings;
class QSpinBox;
class QStackedWidget;
class QToolButton;

namespace armmimic::gui {

class ParameterForm;

class EngineSettingsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit EngineSettingsPanel(QWidget* parent = nullptr);

  // Everything but `inputs`, which belong to the open video.
  AnalysisOptions options() const;
  void setOptions(const AnalysisOptions& options);

  void setRoi(const std::optional<cv::Rect>& roi);
  void setShoulder(const std::optional<cv::Point2d>& shoulder_px);
  void setBackgroundImage(const QString& path);
  // A joint of the start frame, clicked: 0 the shoulder, 1 the elbow, 2 the wrist. The elbow and
  // wrist are used by the tracking engines (lk, hybrid).
  void setJoint(int joint, const cv::Point2d& px);
  // The Auto-calibrate button's work: the shoulder, elbow and wrist in the start frame of
  // `inputs` from the pose network. The message names what failed.
  Status autoCalibrate(const std::vector<std::string>& inputs);
  // Forgets the clicked joints (shoulder, elbow and wrist): the run calibrates itself again.
  // Calibrate from standstill does this once its joints are shown, so that accepting them
  // leaves the run to its own calibration.
  void clearJoints();
  // Whether estimated joints are shown for the operator to accept (enables Accept).
  void setEstimateShown(bool shown);

  void save(QSettings& settings) const;
  void load(QSettings& settings);

  // The editor of one engine parameter, named "<engine>.<key>" ("lk.max_corners"): a QSpinBox,
  // QDoubleSpinBox, QCheckBox or QComboBox. nullptr for an unknown key.
  QWidget* parameterEditor(EngineKind engine, const QString& key) const;
  // The button that shows or hides an engine's "Advanced" section.
  QToolButton* advancedToggle(EngineKind engine) const;
  // The button that puts every parameter of an engine back to its default.
  QToolButton* resetButton(EngineKind engine) const;

  // The field the setting `key` is edited in ("analysis.arm_length": the arm-length image,
  // "lk.window_px": that parameter's editor), or nullptr.
  QWidget* fieldForKey(const QString& key) const;
  // An error in the panel's words: frames and focuses the field of `key` (opening its engine's
  // page and "Advanced" section) and returns "<field label>: <message>"; the message alone when
  // `key` names no field here (engine_settings_errors.cpp).
  QString showError(const QString& key, const QString& message);

 signals:
  void changed();
  void roiChanged(const std::optional<cv::Rect>& roi);
  void shoulderChanged(const std::optional<cv::Point2d>& shoulder_px);
  void autoCalibrateRequested();
  void standstillCalibrateRequested();
  void estimateAccepted();

 private:
  // The engine combo's entries, the parameter forms and their pages (engine_settings_pages.cpp).
  void makeForms();
  // Puts lk's and bgsub's forms on the page of `kind`: the hybrid's, or their own.
  void placeForms(EngineKind kind);
  QWidget* makeInputs();
  QWidget* makeCalibrateRow();
  QLineEdit* fileRow(QWidget* parent, const QString& name, QWidget** row);
  void updateEnabled();

  // Fields the panel does not show keep the values last given to setOptions().
  AnalysisOptions base_;

  QComboBox* engine_;
  QStackedWidget* pages_;
  static constexpr int kEngines = 5;
  ParameterForm* forms_[kEngines] = {};  // indexed by EngineKind
  QWidget* own_page_[kEngines] = {};     // each engine's page in pages_
  QWidget* hybrid_part_[2] = {};         // the hybrid page's places for bgsub's and lk's forms
  // Inputs.
  QComboBox* bg_mode_;
  QLineEdit* background_;
  QWidget* background_row_;
  QSpinBox* bg_frames_;
  QLineEdit* arm_length_;
  QWidget* arm_length_row_;
  QLineEdit* reference_;
  QWidget* reference_row_;
  QSpinBox* start_;
  QGroupBox* shoulder_box_;
  QDoubleSpinBox* shoulder_x_;
  QDoubleSpinBox* shoulder_y_;
  QGroupBox* elbow_wrist_box_;
  QDoubleSpinBox* elbow_[2];
  QDoubleSpinBox* wrist_[2];
  QPushButton* auto_calibrate_;
  QPushButton* standstill_calibrate_;
  QPushButton* accept_estimate_;
  bool estimate_shown_ = false;
  QGroupBox* roi_box_;
  QSpinBox* roi_[4];
};

}  // namespace armmimic::gui
