#include "plots/samplecsvwriter.h"

#include "model/params.h"
#include "plots/samplebuffer.h"
#include "telemetry/recording.h"

#include <QSaveFile>

#include <cmath>

namespace hatpic {

namespace {

void appendNumber(QByteArray &line, double value)
{
    if (std::isnan(value))
        return; // an empty field, as the recorder writes it
    const std::string text = formatNumber(value);
    line.append(text.data(), static_cast<qsizetype>(text.size()));
}

} // namespace

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
        appendNumber(line, buffer.time(i));
        for (Channel channel : kAllChannels) {
            line.append(',');
            appendNumber(line, buffer.value(channel, i));
        }
        line.append(',');
        line.append(QByteArray::number(buffer.flags(i)));
        line.append(",\n");
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
