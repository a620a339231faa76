// The fault summary that hatpic-sim and hatpic-fw-host print on stderr at exit and on SIGUSR1
// (docs/simulator.md § Faults).
#pragma once

#include "link/faultinjector.h"

#include <QString>

#include <cstdio>

namespace hatpic {

//! "PROGRAM: faults SPEC, seed N:" then FaultInjector::summary()'s lines, indented.
inline void printFaultReport(const char *program, const FaultInjector &faults, quint64 seed)
{
    QString text = QStringLiteral("faults ") + faults.spec().toString() +
                   QStringLiteral(", seed ") + QString::number(seed) + u':' + u'\n' +
                   faults.summary();
    text.replace(u'\n', u'\n' + QString::fromLatin1(program) + QStringLiteral(":   "));
    std::fprintf(stderr, "%s: %s\n", program, qPrintable(text));
    std::fflush(stderr);
}

} // namespace hatpic
