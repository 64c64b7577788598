// EngineSettingsPanel: the engine choice, its parameters and the analysis inputs, edited in the
// same AnalysisOptions/EngineOptions structs the CLI fills from its flags.
#pragma once

#include <QWidget>

#include "armmimic/engines/analysis.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLineEdit;
class QSettings;
class QSpinBox;
class QStackedWidget;

namespace armmimic::gui {

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

  void save(QSettings& settings) const;
  void load(QSettings& settings);

 signals:
  void changed();
  void roiChanged(const std::optional<cv::Rect>& roi);
  void shoulderChanged(const std::optional<cv::Point2d>& shoulder_px);

 private:
  QWidget* makeInputs();
  QWidget* makeBgsubPage();
  QWidget* makeLkPage();
  QWidget* makeMarkerPage();
  QLineEdit* fileRow(QWidget* parent, const QString& name, QWidget** row);
  void updateEnabled();

  // Fields the panel does not show keep the values last given to setOptions().
  AnalysisOptions base_;

  QComboBox* engine_;
  QStackedWidget* pages_;
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
  QGroupBox* roi_box_;
  QSpinBox* roi_[4];
  // bgsub.
  QSpinBox* threshold_;
  QSpinBox* bg_standstill_;
  QDoubleSpinBox* straight_ratio_;
  QSpinBox* closing_;
  QCheckBox* bg_thesis_;
  // lk.
  QSpinBox* lk_standstill_;
  QDoubleSpinBox* initial_upper_;
  QDoubleSpinBox* initial_fore_;
  QSpinBox* still_drop_;
  QCheckBox* lk_thesis_;
  // marker.
  QSpinBox* median_;
  QSpinBox* low_;
  QSpinBox* high_;
  QSpinBox* flood_;
  QCheckBox* marker_thesis_;
};

}  // namespace armmimic::gui
