#include "sim_controller.h"

namespace armmimic::gui {

SimController::SimController(QObject* parent) : QObject(parent) {}
SimController::~SimController() { stop(); }

bool SimController::start(double time_scale, const robot::JointLimits& limits, QString* error) {
  stop();
  sim::EmulatorOptions options;
  options.time_scale = time_scale;
  options.limits = limits;
  auto server = std::make_unique<sim::PtyServer>(options);
  const Status st = server->Start();
  if (!st) {
    if (error) *error = QString::fromStdString(st.message());
    return false;
  }
  server_ = std::move(server);
  return true;
}

void SimController::stop() {
  if (server_) server_->Stop();
  server_.reset();
}

QString SimController::devicePath() const {
  return server_ ? QString::fromStdString(server_->device_path()) : QString();
}

robot::JointArray SimController::joints() const {
  return server_ ? server_->joints() : robot::JointArray{0, -90, 0, 0, 0, 0};
}

int SimController::movesExecuted() const {
  return server_ ? static_cast<int>(server_->log().size()) : 0;
}

}  // namespace armmimic::gui
