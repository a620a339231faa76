// The one place that words, for a person, what the device session reports in codes and numbers:
// the state's detail (connecting, connected, a link lost and why), a command's outcome and the
// session's notices. The tuner, hatpicctl and hatpic-bridge all print these sentences; they are
// translatable (context "hatpic::SessionWording"). No widgets; callable from any thread.
#pragma once

#include "session/sessiontypes.h"

#include <QCoreApplication>
#include <QString>

namespace hatpic {

class SessionWording
{
    Q_DECLARE_TR_FUNCTIONS(hatpic::SessionWording)
public:
    //! "/dev/ttyUSB0 at 921600 baud", or "the simulated joystick" (no serial line, no baud).
    static QString port(const StateDetail &detail);
    //! One sentence for the status bar, the link banner and the programs' stderr, e.g. "Lost
    //! /dev/ttyUSB0 at 921600 baud: reading from the port failed"; empty for Kind::None.
    static QString stateDetail(const StateDetail &detail);
    //! e.g. "Not connected: a recording starts once a device is connected."
    static QString notice(const SessionNotice &notice);

    //! Why a request failed, one sentence, e.g. "The device rejected K_max (field 3):
    //! OUT_OF_RANGE; its parameters are unchanged."; empty when it was done. A push that failed
    //! part-way adds what it had changed (appliedBeforeFailure()).
    static QString commandFailure(const Outcome &outcome);
    //! The same outcome as a short clause for the editor's sync line, e.g. "device rejected:
    //! OUT_OF_RANGE (K_max)", "timeout: the device did not answer"; empty when it was done.
    static QString commandFailureBrief(const Outcome &outcome);
    //! Why a device cannot render effects, as a clause: "it runs the published firmware, legacy
    //! protocol" or "its firmware does not announce the effects capability".
    static QString noEffectsReason(bool legacy);
    //! Why a device has no passivity controller, as a clause of the same kind.
    static QString noPassivityReason(bool legacy);
    //! The summary of a device's lines not shown: "(72812 more lines from the device not shown:
    //! at most 20 a second are)".
    static QString deviceLinesHeldBack(quint64 lines, int perInterval, int intervalMs);

    //! What a push that failed part-way left in force (outcome::Stopped::applied), as
    //! sentences to follow commandFailure()'s: "It had accepted the parameters (SET_PARAMS, read
    //! back): those are in force." — and, when the step that failed may or may not have taken
    //! effect, that its part is unknown. Empty when the push changed nothing.
    static QString appliedBeforeFailure(const Outcome &outcome);

private:
    static QString rejection(const outcome::Refused &refused);
    static QString unsupported(const outcome::Unsupported &unsupported);
    static QString invalid(const Request &request, const outcome::Invalid &invalid);
};

} // namespace hatpic
