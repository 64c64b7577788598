// The GUI's words for an error keyed by a setting (Status::key()): the field the setting is
// edited in is framed in red and takes the focus, and the message starts with the field's label
// instead of a command-line flag. The frame goes as soon as the field is changed.
#pragma once

#include <QString>

class QWidget;

namespace armmimic::gui {

// Frames `field` as the one an error is about and gives it the focus; the frame goes when the
// field's value changes (or ClearFieldError).
void MarkFieldError(QWidget* field);
void ClearFieldError(QWidget* field);
bool HasFieldError(const QWidget* field);

// The label the user sees for `field`: its form row's label, a check box's or group box's own
// text, without a keyboard accelerator's '&'.
QString FieldLabel(const QWidget* field);

}  // namespace armmimic::gui
