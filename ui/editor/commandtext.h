// The tuner's words (translatable) for why a device command failed, from the codes and
// numbers of its CommandResult (the session composes no sentence).
#pragma once

#include "session/sessiontypes.h"

#include <QCoreApplication>
#include <QString>

namespace hatpic {

class CommandText
{
    Q_DECLARE_TR_FUNCTIONS(CommandText)
public:
    //! e.g. "The device rejected K_max (field 3): OUT_OF_RANGE; its parameters are unchanged.";
    //! empty for Ok.
    static QString commandFailure(const CommandResult &result);
    //! Why a device cannot render effects, as a clause: "it runs the published firmware
    //! (legacy protocol)" or "its firmware does not announce the effects capability".
    static QString noEffectsReason(bool legacy);

private:
    static QString rejection(const CommandResult &result);
};

} // namespace hatpic
