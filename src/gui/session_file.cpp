#include "session_file.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "armmimic/core/output_file.h"
#include "armmimic/engines/option_fields.h"
#include "armmimic/engines/removed_options.h"

namespace armmimic::gui {
namespace {

constexpr const char* kFormat = "armmimic-session";
constexpr int kVersion = 1;

QString Relative(const QDir& dir, const std::string& path) {
  if (path.empty()) return QString();
  const QString p = QString::fromStdString(path);
  const QString rel = dir.relativeFilePath(QFileInfo(p).absoluteFilePath());
  return rel.startsWith("..") || p.startsWith("camera:") || p.contains("://") ? p : rel;
}

std::string Absolute(const QDir& dir, const QJsonValue& v) {
  const QString p = v.toString();
  if (p.isEmpty() || p.startsWith("camera:") || p.contains("://")) return p.toStdString();
  return QDir::cleanPath(dir.absoluteFilePath(p)).toStdString();
}

QJsonValue Point(const std::optional<cv::Point2d>& p) {
  return p ? QJsonValue(QJsonArray{p->x, p->y}) : QJsonValue();
}

// A point entry: null or [x, y]. `ok` turns false (and `bad` names the key) when malformed.
std::optional<cv::Point2d> ReadPoint(const QJsonObject& o, const char* key, QString* bad) {
  const QJsonValue v = o.value(key);
  if (v.isUndefined() || v.isNull()) return std::nullopt;
  const QJsonArray a = v.toArray();
  if (a.size() != 2 || !a[0].isDouble() || !a[1].isDouble()) {
    *bad = QString("analysis.%1 (expected [x, y] or null)").arg(key);
    return std::nullopt;
  }
  return cv::Point2d(a[0].toDouble(), a[1].toDouble());
}

QJsonObject WriteAnalysis(const AnalysisOptions& o, const QDir& dir) {
  QJsonObject a;
  a["engine"] = EngineName(o.engine.kind);
  QJsonObject params;  // every engine's changed parameters, so switching engines keeps them
  for (EngineKind kind : AllEngineKinds()) {
    EngineOptions e = o.engine;
    e.kind = kind;
    for (const auto& [key, value] : ChangedEngineOptions(e)) {
      params[QString::fromStdString(key)] = QString::fromStdString(value);
    }
  }
  a["parameters"] = params;
  a["background"] = Relative(dir, o.background_path);
  a["background_frames"] = o.background_frames;
  a["arm_length"] = Relative(dir, o.arm_length_path);
  a["reference"] = Relative(dir, o.reference_path);
  a["start"] = o.start;
  a["shoulder"] = Point(o.shoulder_px);
  a["elbow"] = Point(o.elbow_px);
  a["wrist"] = Point(o.wrist_px);
  a["roi"] = o.roi ? QJsonValue(QJsonArray{o.roi->x, o.roi->y, o.roi->width, o.roi->height})
                   : QJsonValue();
  return a;
}

// Reads the analysis entry into *o; the settings this version removed go to *ignored.
QString ReadAnalysis(const QJsonObject& a, const QDir& dir, AnalysisOptions* o,
                     std::vector<std::string>* ignored) {
  if (!ParseEngineKind(a.value("engine").toString().toStdString(), &o->engine.kind)) {
    return "analysis.engine (expected bgsub, lk, marker, pose or hybrid)";
  }
  const QJsonObject params = a.value("parameters").toObject();
  for (auto it = params.begin(); it != params.end(); ++it) {
    if (FindRemovedEngineOption(it.key().toStdString())) {
      ignored->push_back(it.key().toStdString());
      continue;
    }
    const Status st =
        SetEngineOption((it.key() + "=" + it.value().toString()).toStdString(), &o->engine);
    if (!st) return "analysis.parameters: " + QString::fromStdString(st.message());
  }
  o->background_path = Absolute(dir, a.value("background"));
  o->background_frames = std::max(0, a.value("background_frames").toInt());
  o->arm_length_path = Absolute(dir, a.value("arm_length"));
  o->reference_path = Absolute(dir, a.value("reference"));
  o->start = std::max(0, a.value("start").toInt());
  QString bad;
  o->shoulder_px = ReadPoint(a, "shoulder", &bad);
  o->elbow_px = ReadPoint(a, "elbow", &bad);
  o->wrist_px = ReadPoint(a, "wrist", &bad);
  const QJsonValue roi = a.value("roi");
  if (roi.isArray()) {
    const QJsonArray r = roi.toArray();
    if (r.size() != 4) return "analysis.roi (expected [x, y, w, h] or null)";
    o->roi = cv::Rect(r[0].toInt(), r[1].toInt(), r[2].toInt(), r[3].toInt());
  }
  return bad;
}

}  // namespace

QString WriteSession(const QString& path, const Session& s) {
  const QDir dir = QFileInfo(path).absoluteDir();
  QJsonObject root;
  root["format"] = kFormat;
  root["version"] = kVersion;
  QJsonArray inputs;
  for (const QString& in : s.inputs) inputs.append(Relative(dir, in.toStdString()));
  root["inputs"] = inputs;
  root["frame"] = s.frame;
  root["analysis"] = WriteAnalysis(s.options, dir);
  root["angles"] = s.angle_text.isEmpty() ? QJsonValue() : QJsonValue(s.angle_text);
  if (!s.right_angle_text.isEmpty()) root["angles_right"] = s.right_angle_text;
  const QByteArray bytes = QJsonDocument(root).toJson(QJsonDocument::Indented);
  const Status st = WriteOutputFile(path.toStdString(), bytes.toStdString());
  return st ? QString() : QString::fromStdString(st.message());
}

QString ReadSession(const QString& path, Session* s) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return QString("%1: %2").arg(path, file.errorString());
  QJsonParseError error;
  const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &error);
  if (doc.isNull()) {
    return QString("%1: not a session file: %2 at byte %3")
        .arg(path, error.errorString())
        .arg(error.offset);
  }
  const QJsonObject root = doc.object();
  if (root.value("format").toString() != kFormat) {
    return QString("%1: not a session file (no \"format\": \"%2\")").arg(path, kFormat);
  }
  if (root.value("version").toInt() != kVersion) {
    return QString("%1: session version %2, this version reads %3")
        .arg(path)
        .arg(root.value("version").toInt())
        .arg(kVersion);
  }
  const QDir dir = QFileInfo(path).absoluteDir();
  Session out;
  for (const QJsonValue& v : root.value("inputs").toArray()) {
    out.inputs << QString::fromStdString(Absolute(dir, v));
  }
  out.frame = std::max(0, root.value("frame").toInt());
  std::vector<std::string> ignored;
  const QString bad = ReadAnalysis(root.value("analysis").toObject(), dir, &out.options, &ignored);
  if (!bad.isEmpty()) return QString("%1: %2").arg(path, bad);
  out.ignored = QString::fromStdString(DescribeIgnoredEngineOptions(ignored));
  out.angle_text = root.value("angles").toString();
  out.right_angle_text = root.value("angles_right").toString();
  *s = out;
  return QString();
}

FileKind ClassifyFile(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix == "tsv") return FileKind::kAngleFile;
  if (suffix == "val") return FileKind::kValProgram;
  if (suffix == kSessionSuffix) return FileKind::kSession;
  if (suffix == "json") {
    // The keys are written in sorted order, so "format" can follow a long "angles" text:
    // the whole document is parsed rather than its first bytes searched.
    QFile f(path);
    constexpr qint64 kMaxSessionBytes = 256ll << 20;
    if (f.open(QIODevice::ReadOnly) && f.size() <= kMaxSessionBytes) {
      const QJsonDocument doc = QJsonDocument::fromJson(f.readAll());
      if (doc.isObject() && doc.object().value("format").toString() == kFormat) {
        return FileKind::kSession;
      }
    }
  }
  return FileKind::kMedia;
}

}  // namespace armmimic::gui
