// What the screenshot programs share: the arguments OUT.png [WIDTH HEIGHT], settings kept apart
// from the user's, the real main window at that size connected to the built-in simulator (its
// gentle hand), the program's own staging, and a grab of the window after `grabMs`.
#pragma once

#include "window/mainwindow.h"

#include <QApplication>
#include <QStandardPaths>
#include <QTimer>

#include <cstdio>
#include <functional>

namespace hatpic {

//! Runs the screenshot program `name`; `stage` sets up what is to be seen (it may start its own
//! timers) once the window is connected. Returns the exit code: 0 written, 1 not, 2 usage.
inline int runScreenshot(int argc, char *argv[], const char *name, int grabMs,
                         const std::function<void(MainWindow &window, QSize size)> &stage)
{
    QApplication app(argc, argv);
    const QSize size = argc == 4 ? QSize(QString::fromLocal8Bit(argv[2]).toInt(),
                                         QString::fromLocal8Bit(argv[3]).toInt())
                                 : QSize(1400, 900);
    if ((argc != 2 && argc != 4) || size.isEmpty()) {
        std::fprintf(stderr, "usage: %s OUT.png [WIDTH HEIGHT]\n", name);
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
    stage(window, size);
    QTimer::singleShot(grabMs, &window, [&window, out] {
        const bool ok = window.grab().save(out);
        std::fprintf(stderr, "%s %s\n", ok ? "wrote" : "could not write", qPrintable(out));
        QApplication::exit(ok ? 0 : 1);
    });
    return app.exec();
}

} // namespace hatpic
