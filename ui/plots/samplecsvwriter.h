// Writes the samples of a time range as CSV, in the column layout of a recording
// (recordingColumns(): the sample columns, then an empty event), so an exported view opens in
// replay like any recording. Rows come from the one sample row writer (appendSampleCsvRow):
// SI values in the recordings' number format, NaN (a quantity the protocol does not carry) as
// an empty field.
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
