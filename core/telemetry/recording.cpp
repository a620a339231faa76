#include "recording.h"

#include "telemetry/samplecolumns.h"

#include <QDir>
#include <QFileInfo>

namespace hatpic {

QStringList recordingColumns(int axes, bool tilt)
{
    QStringList columns;
    for (const SampleColumn &column : kSampleColumns)
        columns << QString::fromUtf8(column.name.data(),
                                     static_cast<qsizetype>(column.name.size()));
    for (const QByteArray &extra : extraSampleColumns(axes, tilt))
        columns << QString::fromLatin1(extra);
    columns << QStringLiteral("event");
    return columns;
}

QString recordingMetadataPath(const QString &csvPath)
{
    const QFileInfo info(csvPath);
    const QString base = info.suffix().compare(u"csv", Qt::CaseInsensitive) == 0
                             ? info.completeBaseName()
                             : info.fileName();
    return info.dir().filePath(base + u".json");
}

} // namespace hatpic
