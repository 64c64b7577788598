// "Capture from camera" as an operator uses it, with no camera attached: the dialog takes a
// stream URL, the preview shows the stream, and the live analysis updates the overlay as frames
// arrive. The stream is an MJPEG-over-HTTP "IP camera" served from this process (the format
// common network cameras send), fed with the frames of the synthetic scene.
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QInputDialog>
#include <QPointer>
#include <QSet>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>
#include <opencv2/imgcodecs.hpp>

#include "analysis_job.h"
#include "app_actions.h"
#include "armmimic/core/video_source.h"
#include "engine_settings_panel.h"
#include "gui_fixture.h"
#include "log_view.h"
#include "main_window.h"
#include "video_player.h"
#include "video_view.h"

namespace armmimic::test {
namespace {

using gui::MainWindow;

// Serves `frames` (JPEG) as multipart/x-mixed-replace to every client, each from the first
// frame, one frame per `period_ms`, then closes the connection (the camera "goes away").
class MjpegServer : public QObject {
 public:
  MjpegServer(std::vector<QByteArray> frames, int period_ms)
      : frames_(std::move(frames)), period_ms_(period_ms) {
    connect(&server_, &QTcpServer::newConnection, this, [this] {
      while (QTcpSocket* s = server_.nextPendingConnection()) serve(s);
    });
  }
  bool listen() { return server_.listen(QHostAddress::LocalHost, 0); }
  QString url() const {
    return QString("http://127.0.0.1:%1/stream.mjpg").arg(server_.serverPort());
  }
  int clients() const { return clients_; }

 private:
  void serve(QTcpSocket* socket) {
    ++clients_;
    QPointer<QTcpSocket> s(socket);
    auto* request = new QByteArray;
    connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
    connect(socket, &QTcpSocket::readyRead, this, [this, s, request] {
      if (!s || request->contains("\r\n\r\n")) return;
      request->append(s->readAll());
      if (!request->contains("\r\n\r\n")) return;
      s->write(
          "HTTP/1.0 200 OK\r\n"
          "Content-Type: multipart/x-mixed-replace; boundary=frame\r\n"
          "Cache-Control: no-cache\r\n\r\n");
      auto* timer = new QTimer(s);
      auto next = std::make_shared<std::size_t>(0);
      connect(timer, &QTimer::timeout, s, [this, s, timer, next] {
        if (s->state() != QAbstractSocket::ConnectedState) {  // the client left
          timer->stop();
          return;
        }
        if (*next >= frames_.size()) {
          timer->stop();
          s->disconnectFromHost();
          return;
        }
        const QByteArray& jpeg = frames_[(*next)++];
        s->write("--frame\r\nContent-Type: image/jpeg\r\nContent-Length: " +
                 QByteArray::number(jpeg.size()) + "\r\n\r\n");
        s->write(jpeg);
        s->write("\r\n");
      });
      timer->start(period_ms_);
    });
    connect(socket, &QObject::destroyed, this, [request] { delete request; });
  }

  QTcpServer server_;
  std::vector<QByteArray> frames_;
  int period_ms_;
  int clients_ = 0;
};

std::vector<QByteArray> JpegFrames(const std::string& video) {
  Status st;
  std::unique_ptr<VideoSource> source = VideoSource::Open({video}, &st);
  EXPECT_TRUE(source) << st.message();
  std::vector<QByteArray> frames;
  Frame frame;
  while (source && source->Read(&frame, &st)) {
    std::vector<uchar> bytes;
    cv::imencode(".jpg", frame.image, bytes, {cv::IMWRITE_JPEG_QUALITY, 95});
    frames.emplace_back(reinterpret_cast<const char*>(bytes.data()), int(bytes.size()));
  }
  return frames;
}

// Answers the "Capture from camera" dialog with `text` as soon as it is up.
void AnswerCameraDialog(const QString& text, bool* answered) {
  auto* poll = new QTimer;
  QObject::connect(poll, &QTimer::timeout, poll, [poll, text, answered] {
    auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
    if (!dialog) return;
    dialog->setTextValue(text);
    dialog->accept();
    *answered = true;
    poll->deleteLater();
  });
  poll->start(10);
}

int VisibleDialogs() {
  int n = 0;
  for (QWidget* w : QApplication::topLevelWidgets()) {
    if (qobject_cast<QDialog*>(w) && w->isVisible()) ++n;
  }
  return n;
}

class CameraCaptureTest : public GuiTest {};

TEST_F(CameraCaptureTest, StreamPreviewAndLiveAnalysisUpdateTheOverlay) {
  const GuiScenes& s = scenes();
  const std::vector<QByteArray> frames = JpegFrames(s.video());
  const int total = s.background_frames + s.standstill_frames + s.motion_frames;
  ASSERT_EQ(static_cast<int>(frames.size()), total);
  MjpegServer camera(frames, 15);
  ASSERT_TRUE(camera.listen());

  MainWindow w;
  w.resize(1200, 800);
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  bool answered = false;
  AnswerCameraDialog(camera.url(), &answered);
  w.actions()->camera->trigger();  // File > Capture from camera…
  ASSERT_TRUE(answered);
  ASSERT_TRUE(WaitUntil([&] { return w.player()->isOpen() && !w.view()->image().isNull(); }))
      << w.log()->text().toStdString();
  EXPECT_TRUE(w.player()->isLive());
  EXPECT_EQ(w.player()->inputs(), QStringList{camera.url()});
  EXPECT_EQ(w.log()->errorCount(), 0) << w.log()->text().toStdString();

  AnalysisOptions o = s.BgsubProtocol();
  w.settingsPanel()->setOptions(o);
  // Watch the overlay while the analysis reads the stream: it must change as frames arrive.
  QSet<QString> orientations;
  QSet<int> frames_shown;
  QTimer watch;
  QObject::connect(&watch, &QTimer::timeout, [&] {
    if (w.view()->measurement() && w.view()->measurement()->phase == MeasurementPhase::kOk) {
      orientations.insert(w.view()->overlayTexts().orientation);
      frames_shown.insert(w.view()->frameIndex());
    }
  });
  watch.start(5);
  ASSERT_TRUE(w.startAnalysis()) << w.log()->text().toStdString();
  EXPECT_FALSE(w.player()->isOpen());  // the analysis reads the stream itself
  ASSERT_TRUE(WaitUntil([&] { return !w.job()->isRunning(); }, 60000));
  watch.stop();
  ASSERT_FALSE(w.job()->resultPath().isEmpty()) << w.log()->text().toStdString();
  EXPECT_GE(camera.clients(), 2);  // the preview and the analysis each connected

  // Every motion frame of the stream was analysed, and the overlay followed along the way.
  EXPECT_EQ(w.results().rows(), s.motion_frames);
  EXPECT_GE(frames_shown.size(), 3) << "the overlay did not update during the live analysis";
  EXPECT_GE(orientations.size(), 3);
  ASSERT_TRUE(w.view()->measurement().has_value());
  EXPECT_EQ(w.view()->frameIndex(), total - 1);
  EXPECT_EQ(w.view()->measurement()->frame, total - 1);
  // The frame counter of a live source shows no total.
  EXPECT_EQ(w.view()->overlayTexts().frame, QString("frame %1").arg(total - 1));
}

TEST_F(CameraCaptureTest, AMissingCameraIsReportedOnceWithoutADialogStorm) {
  MainWindow w;
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  bool answered = false;
  AnswerCameraDialog("7", &answered);  // a bare number means camera:7
  w.actions()->camera->trigger();
  ASSERT_TRUE(answered);
  ASSERT_TRUE(WaitUntil([&] { return w.log()->errorCount() >= 1; }, 20000));
  QTest::qWait(300);
  EXPECT_EQ(w.log()->errorCount(), 1) << w.log()->text().toStdString();
  EXPECT_NE(w.log()->text().indexOf("camera:7"), -1) << w.log()->text().toStdString();
  EXPECT_FALSE(w.player()->isOpen());
  EXPECT_EQ(VisibleDialogs(), 0);
  // Asking for the analysis now names what is missing, again without a modal box.
  EXPECT_FALSE(w.startAnalysis());
  EXPECT_EQ(w.log()->errorCount(), 2);
  EXPECT_EQ(VisibleDialogs(), 0);
}

TEST_F(CameraCaptureTest, AFailedCaptureKeepsTheOpenVideoAndItsResults) {
  const GuiScenes& s = scenes();
  MainWindow w;
  ShowAndAnalyze(w);
  ASSERT_EQ(w.results().rows(), s.motion_frames);

  w.openInputs({"camera:7"});
  ASSERT_TRUE(WaitUntil([&] { return w.log()->errorCount() == 1; }, 20000));
  EXPECT_TRUE(w.player()->isOpen());
  EXPECT_EQ(w.player()->inputs(), QStringList{QString::fromStdString(s.video())});
  EXPECT_EQ(w.results().rows(), s.motion_frames);
  const int frame = s.background_frames + s.standstill_frames + 5;
  w.player()->seek(frame);
  ASSERT_TRUE(WaitUntil([&] { return w.view()->frameIndex() == frame; }));
  EXPECT_TRUE(w.view()->measurement().has_value());
  EXPECT_TRUE(w.exportAngles(QString::fromStdString(tmp_.file("kept.tsv"))))
      << w.log()->text().toStdString();
}

}  // namespace
}  // namespace armmimic::test
