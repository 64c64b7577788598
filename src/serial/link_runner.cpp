#include "armmimic/serial/link_runner.h"

#include <QEventLoop>
#include <QTimer>

namespace armmimic::serial {

bool RunToEnd(SerialLink& link, std::vector<robot::LinkLine> lines, const std::string& source,
              const std::function<std::string()>& interrupted) {
  QEventLoop loop;
  bool ok = false;
  auto done = QObject::connect(&link, &SerialLink::finished, &loop, [&](bool result) {
    ok = result;
    loop.quit();
  });
  QTimer poll;
  poll.setInterval(50);
  QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
    if (!interrupted) return;
    const std::string reason = interrupted();
    if (!reason.empty()) link.Cancel(reason);
  });
  poll.start();
  link.Start(std::move(lines), source);
  if (!link.protocol().finished()) loop.exec();
  QObject::disconnect(done);
  return ok || link.protocol().state() == robot::LinkState::kDone;
}

}  // namespace armmimic::serial
