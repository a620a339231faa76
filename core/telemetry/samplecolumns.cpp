#include "samplecolumns.h"

#include "telemetry/numbertext.h"

#include <algorithm>
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

namespace {

void appendNumber(QByteArray &row, double value)
{
    if (!std::isnan(value))
        row += compactNumberText(value).toLatin1();
}

int axesOf(int axes)
{
    return std::clamp(axes, 1, kMaxAxes);
}

} // namespace

QList<QByteArray> extraSampleColumns(int axes, bool tilt)
{
    QList<QByteArray> columns;
    for (int n = 2; n <= axesOf(axes); ++n) {
        for (const AxisColumn &column : kAxisColumns) {
            columns << QByteArray(column.name.data(), qsizetype(column.name.size())) + '_' +
                           QByteArray::number(n);
        }
    }
    if (tilt) {
        for (const TiltColumn &column : kTiltColumns)
            columns << QByteArray(column.name.data(), qsizetype(column.name.size()));
    }
    return columns;
}

void appendExtraCsvFields(QByteArray &row, const Sample &sample, int axes, bool tilt)
{
    for (int n = 2; n <= axesOf(axes); ++n) {
        const AxisSample *axis = sample.axis(n);
        for (const AxisColumn &column : kAxisColumns) {
            row += ',';
            if (axis)
                appendNumber(row, axis->*column.value);
        }
    }
    if (tilt) {
        for (const TiltColumn &column : kTiltColumns) {
            row += ',';
            if (sample.board)
                appendNumber(row, *sample.board.*column.value);
        }
    }
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
        appendNumber(row, sample.*column.value);
    }
}

} // namespace hatpic
