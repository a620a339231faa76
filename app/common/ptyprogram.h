// The start-up every program behind a pseudo-terminal shares (hatpic-sim, hatpic-fw-host,
// hatpic-servo-sim): start the host, make the --link symlink, print the terminal's path as the
// first stdout line.
#pragma once

#include <QString>

#include <cstdio>

namespace hatpic {

//! Starts `host` (SimulatorHost, FirmwareHost, ServoBusHost: start(), createLink(), stop(),
//! slavePath()) and, when `link` is set, makes the symlink. On failure `printError` gets the
//! one sentence, the host is stopped, and the result is false. On success the slave's path
//! goes to stdout as the first line, flushed.
template<typename Host, typename PrintError>
bool serveOnPseudoTerminal(Host &host, const QString &link, PrintError printError)
{
    if (const QString error = host.start(); !error.isEmpty()) {
        printError(error);
        return false;
    }
    if (!link.isEmpty()) {
        if (const QString error = host.createLink(link); !error.isEmpty()) {
            printError(error);
            host.stop();
            return false;
        }
    }
    std::fprintf(stdout, "%s\n", qPrintable(host.slavePath()));
    std::fflush(stdout);
    return true;
}

} // namespace hatpic
