// FocusReturn: after any modal dialog of the window closes (a question, a file dialog, the send
// confirmation), the window is activated again, so its keys act at once: Esc aborts a send that
// the confirmation has just started, without a click on the window first. A window manager may
// otherwise leave the focus nowhere once the dialog is gone.
#pragma once

class QWidget;

namespace armmimic::gui {

// Installs the watch for `window` (an application-wide event filter owned by `window`).
void ReturnFocusAfterDialogs(QWidget* window);

}  // namespace armmimic::gui
