// measure_screenshot OUT.png [WIDTH HEIGHT] — the measuring tools in the real main window,
// connected to the built-in simulator with its gentle hand: after a few seconds the plots are
// paused, the cursors A and B are on, the XY view and the torque breakdown docks are open, and
// the window is grabbed at 1400×900 (or WIDTH×HEIGHT). Run it under Xvfb:
//   xvfb-run -a -s "-screen 0 1280x720x24" build/bench/measure_screenshot
//   docs/screenshot-measure-1280x720.png 1280 720
#include "plots/measurecursors.h"
#include "plots/plotpanel.h"
#include "recording/plotfeed.h"
#include "window/mainwindow.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
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
        std::fprintf(stderr, "usage: measure_screenshot OUT.png [WIDTH HEIGHT]\n");
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
    auto *xy = window.findChild<QDockWidget *>(QStringLiteral("xyDock"));
    auto *breakdown = window.findChild<QDockWidget *>(QStringLiteral("breakdownDock"));
    xy->show();
    breakdown->show();
    if (size.width() >= 1600) { // room for both side by side; else they stay tabs
        // (A dock in a tab group would take the other as a tab: out of it first.)
        window.removeDockWidget(xy);
        window.removeDockWidget(breakdown);
        window.addDockWidget(Qt::BottomDockWidgetArea, xy);
        window.splitDockWidget(xy, breakdown, Qt::Horizontal);
        xy->show();
        breakdown->show();
    }

    QTimer::singleShot(9000, &window, [&window] {
        window.findChild<PlotFeed *>(QStringLiteral("plotFeed"))->togglePause();
        auto *plots = window.findChild<PlotPanel *>(QStringLiteral("plotPanel"));
        window.findChild<QAction *>(QStringLiteral("measureAction"))->trigger();
        plots->measure()->setTime(0, plots->viewEnd() - 4.2);
        plots->measure()->setTime(1, plots->viewEnd() - 1.7);
        plots->repaintNow();
    });
    QTimer::singleShot(9800, &window, [&window, out] {
        const bool ok = window.grab().save(out);
        std::fprintf(stderr, "%s %s\n", ok ? "wrote" : "could not write", qPrintable(out));
        QApplication::exit(ok ? 0 : 1);
    });
    return app.exec();
}
