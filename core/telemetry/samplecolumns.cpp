#include "samplecolumns.h"

#include "telemetry/numbertext.h"

#include <cmath>

namespace hatpic {

QByteArray sampleCsvHeader()
{
    QByteArray header;
    for (const SampleColumn &column : kSampleColumns) {
        if (!header.isEmpty())
            header += ',';
        header += QByteArrayView(column.name.data(), static_cast<qsizetype>(column.name.size()));
    }
    return header;
}

void appendSampleCsvRow(QByteArray &row, const Sample &sample)
{
    bool first = true;
    for (const SampleColumn &column : kSampleColumns) {
        if (!first)
            row += ',';
        first = false;
        if (column.isFlags()) {
            row += QByteArray::number(sample.flags);
            continue;
        }
        const double value = sample.*column.value;
        if (!std::isnan(value))
            row += compactNumberText(value).toLatin1();
    }
}

} // namespace hatpic
