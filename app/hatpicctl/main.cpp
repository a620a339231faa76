// hatpicctl: command-line access to a HATPIC joystick and to the haptic model (docs/cli.md).
#include "command.h"

#include <QCoreApplication>
#include <QLoggingCategory>

#include <csignal>

int main(int argc, char *argv[])
{
    // A file-size limit (ulimit -f) must fail the write with EFBIG, which the recorder
    // handles (whole rows kept, files closed), instead of killing the process mid-row.
    std::signal(SIGXFSZ, SIG_IGN);
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("hatpicctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(HATPIC_VERSION));
    // Failures are reported once, as a sentence of our own; the library's log lines would
    // repeat them. QT_LOGGING_RULES="hatpic.*=true" brings them back (it takes precedence).
    QLoggingCategory::setFilterRules(QStringLiteral("hatpic.*=false"));
    return hatpic::cli::dispatch(QCoreApplication::arguments());
}
