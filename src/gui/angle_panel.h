// AnglePanel: the Angles dock: the plot with its tools (reset zoom, frames or seconds, save the
// plot as an image, save the frames in view as CSV) and the hover readout; with both arms
// analysed (the pose engine's side both), the arm picked for the plot, the overlay's angles and
// the robot. The form is ui/angle_panel.ui; the tools are also the plot's right-click menu.
#pragma once

#include <memory>

#include <QWidget>

namespace Ui {
class AnglePanelForm;
}

namespace armmimic::gui {

class AnglePlot;

class AnglePanel : public QWidget {
  Q_OBJECT
 public:
  explicit AnglePanel(QWidget* parent = nullptr);
  ~AnglePanel() override;

  AnglePlot* plot() const { return plot_; }
  // What the readout shows ("" when the mouse is not over the plot).
  QString readout() const;
  // Where "Save image…" suggests to write ("scene-plot.png" beside the video).
  void setSuggestedPath(const QString& path) { suggested_path_ = path; }
  // Writes the plot (PNG or SVG from the suffix) and reports it. False on error.
  bool saveImage(const QString& path);
  // Called when the video's frame rate is known: a time axis needs one.
  void updateTimeAxisButton();
  // The arms the results hold: the arm picker shows only for 2 (left and right).
  void setArmCount(int arms);
  // The arm picked: 0 the person's left, 1 the right (0 with one arm).
  int arm() const;
  void setArm(int arm);

 signals:
  // The operator picked the other arm.
  void armChanged(int arm);
  // "Save range as CSV…": the window asks where and writes the rows of the frames in view.
  void rangeCsvRequested();
  void message(const QString& text);
  void errorOccurred(const QString& text);

 private:
  std::unique_ptr<Ui::AnglePanelForm> ui_;
  AnglePlot* plot_;
  QString suggested_path_;
};

}  // namespace armmimic::gui
