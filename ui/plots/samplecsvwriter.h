// Writes the samples of a time range as CSV, in the column layout of a recording
// (t_s, theta, omega, tau, tau_rec, tau_ext, tau_total, v_ref, p_ref, flags, event), so an
// exported view opens in replay like any recording. Values are SI with round-trip digits; NaN
// (a quantity the protocol does not carry) is an empty field, as in a recording.
#pragma once

#include <QString>

namespace hatpic {

class SampleBuffer;

class SampleCsvWriter
{
public:
    //! The header row, without line end.
    static QString header();

    //! Writes every sample with t0 ≤ t_s ≤ t1 to `path` atomically (QSaveFile).
    //! Returns the number of rows written, or −1 with `error` set.
    static qsizetype write(const SampleBuffer &buffer, double t0, double t1, const QString &path,
                           QString *error = nullptr);
};

} // namespace hatpic
