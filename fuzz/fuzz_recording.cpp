// parseRecording (the recording reader; readRecording reads the files and calls the same
// code) on arbitrary bytes.
//
// Input: the CSV, then optionally a 0x00 byte and the JSON sidecar.
// Invariants:
// - a result holds either a recording or an error, never both, never neither;
// - every sample's t_s is finite; warnings are bounded (20 and a closing note);
// - with metadata, events are sorted by time (the CSV alone keeps row order).
#include "fuzzcheck.h"
#include "telemetry/recordingreader.h"

#include <cmath>

using namespace hatpic;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray all =
        QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size));
    const qsizetype split = all.indexOf('\0');
    const QByteArray csv = split < 0 ? all : all.first(split);
    std::optional<QByteArray> metadata;
    if (split >= 0)
        metadata = all.sliced(split + 1);

    const RecordingReadResult result = parseRecording(csv, metadata);
    FUZZ_CHECK(result.recording.has_value() == result.error.isEmpty());
    // 20 + a closing note from the CSV; the metadata adds at most 4 of its own and 4 about
    // its parameters (3 named, 1 counting the rest).
    FUZZ_CHECK(result.warnings.size() <= 21 + (metadata ? 8 : 0));
    if (!result.recording)
        return 0;
    const Recording &rec = *result.recording;
    for (const Sample &s : rec.samples)
        FUZZ_CHECK(std::isfinite(s.t_s));
    for (qsizetype i = 1; rec.hasMetadata && i < rec.events.size(); ++i)
        FUZZ_CHECK(!(rec.events[i].t_s < rec.events[i - 1].t_s));
    return 0;
}
