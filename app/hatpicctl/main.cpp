// hatpicctl: command-line access to a HATPIC joystick and to the haptic model (docs/cli.md).
#include "common/librarylog.h"
#include "rasterimage.h"
#include "subcommand.h"

#include <QCoreApplication>

#include <csignal>

int main(int argc, char *argv[])
{
    // A file-size limit (ulimit -f) must fail the write with EFBIG, which the recorder
    // handles (whole rows kept, files closed), instead of killing the process mid-row.
    std::signal(SIGXFSZ, SIG_IGN);
    // A reader that closes stdout early (`hatpicctl stream | head`) must fail the write with
    // EPIPE, which ends the command with exit 4 ("stdout cannot be written"), instead of
    // killing the process by SIGPIPE (141) before it closes its port and files.
    std::signal(SIGPIPE, SIG_IGN);
    // A QGuiApplication only for a run that draws a PNG; before any other thread starts.
    const std::unique_ptr<QCoreApplication> app = hatpic::cli::makeApplication(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("hatpicctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(HATPIC_VERSION));
    hatpic::cli::silenceLibraryLog(); // failures are reported once, in our own sentences
    return hatpic::cli::dispatch(QCoreApplication::arguments());
}
