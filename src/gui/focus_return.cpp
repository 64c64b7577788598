#include "focus_return.h"

#include <QApplication>
#include <QDialog>
#include <QEvent>
#include <QPointer>
#include <QTimer>
#include <QWidget>

namespace armmimic::gui {
namespace {

class FocusReturn : public QObject {
 public:
  explicit FocusReturn(QWidget* window) : QObject(window), window_(window) {}

  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() != QEvent::Hide) return false;
    auto* dialog = qobject_cast<QDialog*>(watched);
    if (!dialog || !dialog->isModal() || dialog->window() == window_) return false;
    // After the dialog's own hiding is done (its exec() returns first).
    QTimer::singleShot(0, window_, [window = window_] {
      if (!window || !window->isVisible() || QApplication::activeModalWidget()) return;
      window->raise();
      window->activateWindow();
    });
    return false;
  }

 private:
  QPointer<QWidget> window_;
};

}  // namespace

void ReturnFocusAfterDialogs(QWidget* window) { qApp->installEventFilter(new FocusReturn(window)); }

}  // namespace armmimic::gui
