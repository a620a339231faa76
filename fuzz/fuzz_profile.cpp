// parseProfile (the profile loader; readProfile reads a file and calls it) on arbitrary bytes.
//
// Invariants:
// - a result has a profile exactly when it has no errors;
// - an accepted profile serialises to JSON that parses back to the same profile without a
//   warning, and serialising that gives the same bytes.
#include "fuzzcheck.h"
#include "profile/profile.h"

using namespace hatpic;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (qint64(size) > kMaxProfileBytes)
        return 0;
    const QByteArray json(reinterpret_cast<const char *>(data), qsizetype(size));
    const ProfileReadResult result = parseProfile(json);
    FUZZ_CHECK(result.ok() == result.errors.isEmpty());
    if (!result.ok())
        return 0;
    const QByteArray text = serializeProfile(*result.profile);
    const ProfileReadResult back = parseProfile(text);
    FUZZ_CHECK(back.ok() && back.warnings.isEmpty());
    FUZZ_CHECK(*back.profile == *result.profile);
    FUZZ_CHECK(serializeProfile(*back.profile) == text);
    return 0;
}
