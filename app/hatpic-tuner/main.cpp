// hatpic-tuner [--port PATH|sim] [--baud N] [--protocol auto|v2|legacy] [--profile FILE]
//              [--hand SPEC] [--bridge 1|2] [--record FILE.csv] [RECORDING.csv]
// A bad option: one sentence on stderr, exit 4 (common/exitcodes.h), before any window
// (tuneroptions.h). SIGTERM, SIGHUP, SIGINT (and every other signal that would end it and can
// wait) quit as the window's Quit does, without its questions: the recording is closed with
// every row written, the device left without the bridge's force; exit 0 (SIGINT, SIGTERM) or
// 128 + the signal.
#include "common/quitonsignal.h"
#include "hatpic-tuner/tuneroptions.h"
#include "window/mainwindow.h"

#include <QApplication>

#include <csignal>
#include <cstdio>

using namespace hatpic;

int main(int argc, char *argv[])
{
    QApplication::setOrganizationName(QStringLiteral("HATPIC"));
    QApplication::setApplicationName(QStringLiteral("hatpic-tuner"));
    QApplication::setApplicationVersion(QStringLiteral(HATPIC_VERSION));
    const std::variant<TunerOptions, int> options = readTunerOptions(argc, argv);
    if (const int *exitCode = std::get_if<int>(&options))
        return *exitCode;

    QApplication app(argc, argv);
    QApplication::setDesktopFileName(QStringLiteral("hatpic-tuner"));
    if (!quitOnSignals())
        std::fprintf(stderr, "hatpic-tuner: cannot install the signal handlers; a kill will not "
                             "close a recording\n");
    MainWindow window;
    applyTunerOptions(std::get<TunerOptions>(options), window);
    const int code = app.exec();
    // Quit by a signal: the window's destruction below closes the recording and the link.
    const int signal = quitSignal();
    if (signal != 0 && signal != SIGINT && signal != SIGTERM)
        return 128 + signal;
    return code;
}
