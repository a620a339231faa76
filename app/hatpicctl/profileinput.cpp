#include "profileinput.h"

#include "console.h"

namespace hatpic::cli {

std::optional<Profile> loadProfile(const QString &path)
{
    const ProfileReadResult read = readProfile(path);
    for (const QString &warning : read.warnings)
        printNote(u"warning: " + path + u": " + warning);
    if (read.ok())
        return read.profile;
    if (read.errors.size() == 1) {
        printError(u"Cannot use the profile " + path + u": " + asSentence(read.errors.front()));
    } else {
        printError(u"Cannot use the profile " + path + u"; it has " +
                   QString::number(read.errors.size()) + u" errors:");
        for (const QString &error : read.errors)
            printNote(u"  " + error);
    }
    return std::nullopt;
}

} // namespace hatpic::cli
