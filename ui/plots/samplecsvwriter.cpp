#include "plots/samplecsvwriter.h"

#include "plots/samplebuffer.h"
#include "telemetry/recording.h"
#include "telemetry/samplecolumns.h"

#include <QSaveFile>

namespace hatpic {

QString SampleCsvWriter::header()
{
    return recordingColumns().join(u',');
}

qsizetype SampleCsvWriter::write(const SampleBuffer &buffer, double t0, double t1,
                                 const QString &path, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error)
            *error = file.errorString();
        return -1;
    }
    file.write(header().toUtf8() + '\n');
    const qsizetype first = buffer.lowerBound(t0);
    const qsizetype last = buffer.upperBound(t1);
    QByteArray line;
    for (qsizetype i = first; i < last; ++i) {
        line.clear();
        appendSampleCsvRow(line, buffer.sample(i));
        line.append(",\n"); // no event
        file.write(line);
    }
    if (!file.commit()) {
        if (error)
            *error = file.errorString();
        return -1;
    }
    return last - first;
}

} // namespace hatpic
