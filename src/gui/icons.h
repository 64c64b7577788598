// Icons drawn with QPainter at whatever size and device pixel ratio Qt asks for (HiDPI-safe),
// in the palette's text colour so they follow a dark or light scheme.
#pragma once

#include <QIcon>

namespace armmimic::gui {

enum class IconKind {
  kOpen,
  kCamera,
  kPlay,
  kPause,
  kStepBack,
  kStepForward,
  kFirst,
  kLast,
  kAnalyze,
  kStop,
  kExport,
  kSaveImage,
  kRoi,
  kShoulder,
  kPan,
  kZoomIn,
  kZoomOut,
  kZoomFit,
  kBackground,
  kRobot,
  kSend,
  kApp
};

QIcon MakeIcon(IconKind kind);

}  // namespace armmimic::gui
