// tuner_screenshot OUT.png [WIDTH HEIGHT] — makes docs/screenshot.png: the real main window,
// connected to the built-in simulator with its gentle hand, K_max pushed from 0.4 to 0.6 after
// a few seconds (a marker on the time axis, the device curve on the stiffness view), the cursor
// readout on, then a grab of the window at 1400×900 (or WIDTH×HEIGHT). Run it under Xvfb (see
// docs/performance.md):
//   xvfb-run -a -s "-screen 0 1400x900x24" build/bench/tuner_screenshot docs/screenshot.png
//   xvfb-run -a -s "-screen 0 1280x720x24" build/bench/tuner_screenshot
//   docs/screenshot-1280x720.png 1280 720
#include "editor/parametereditor.h"
#include "plots/plotpanel.h"
#include "window/mainwindow.h"

#include <QAction>
#include <QApplication>
#include <QStandardPaths>
#include <QTimer>

#include <cstdio>

using namespace hatpic;

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    const QSize size = argc == 4 ? QSize(QString::fromLocal8Bit(argv[2]).toInt(),
                                         QString::fromLocal8Bit(argv[3]).toInt())
                                 : QSize(1400, 900);
    if ((argc != 2 && argc != 4) || size.isEmpty()) {
        std::fprintf(stderr, "usage: tuner_screenshot OUT.png [WIDTH HEIGHT]\n");
        return 2;
    }
    const QString out = QString::fromLocal8Bit(argv[1]);
    QStandardPaths::setTestModeEnabled(true); // leave the user's settings alone
    QApplication::setOrganizationName(QStringLiteral("hatpic-screenshot"));
    QApplication::setApplicationName(QStringLiteral("hatpic-tuner"));

    MainWindow window;
    window.resize(size);
    window.show();
    ConnectOptions options;
    options.port = QStringLiteral("sim");
    window.connectTo(options);

    QTimer::singleShot(6500, &window, [&window] {
        auto *editor = window.findChild<ParameterEditor *>(QStringLiteral("parameterEditor"));
        DeviceParams params = editor->params();
        params.K_max = 0.6;
        editor->setParams(params, editor->hostParams(), QStringLiteral("K_max"));
        editor->pushAction()->trigger();
    });
    QTimer::singleShot(13800, &window, [&window] {
        auto *plots = window.findChild<PlotPanel *>(QStringLiteral("plotPanel"));
        plots->setCursorTime(plots->viewEnd() - 1.6);
        plots->repaintNow();
    });
    QTimer::singleShot(14200, &window, [&window, out] {
        const bool ok = window.grab().save(out);
        std::fprintf(stderr, "%s %s\n", ok ? "wrote" : "could not write", qPrintable(out));
        QApplication::exit(ok ? 0 : 1);
    });
    return app.exec();
}
