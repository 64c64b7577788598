// SimController: the built-in simulated PUMA controller. It runs the emulator behind a
// pseudo-terminal in this process; the robot panel connects to its device path through the same
// serial code as a real port.
#pragma once

#include <memory>

#include <QObject>
#include <QString>

#include "armmimic/sim/pty_server.h"

namespace armmimic::gui {

class SimController : public QObject {
  Q_OBJECT
 public:
  explicit SimController(QObject* parent = nullptr);
  ~SimController() override;

  // time_scale < 1 runs motions faster than real time.
  bool start(double time_scale, const robot::JointLimits& limits, QString* error);
  void stop();
  bool isRunning() const { return server_ != nullptr; }
  QString devicePath() const;
  robot::JointArray joints() const;
  int movesExecuted() const;

 private:
  std::unique_ptr<sim::PtyServer> server_;
};

}  // namespace armmimic::gui
