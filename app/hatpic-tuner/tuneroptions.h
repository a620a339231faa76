// hatpic-tuner's command line: read and checked before any window (a bad option is one
// sentence on stderr and exit 4, help and version need no display), then applied to the
// window once it exists.
#pragma once

#include "session/sessiontypes.h"
#include "sim/handinput.h"

#include <QString>

#include <optional>
#include <variant>

namespace hatpic {

class MainWindow;

struct TunerOptions
{
    ConnectOptions connection;     //!< port empty: the user connects from the window
    std::optional<HandInput> hand; //!< --hand: the simulated operator's input
    double repaintHz = 0;          //!< --repaint-rate, else the plots' default [Hz]
    double quitAfterSeconds = -1;  //!< --quit-after [s]; < 0: never
    int bridgeRos = 0;             //!< --bridge 1|2; 0: not started
    QString profile;               //!< --profile FILE
    QString record;                //!< --record FILE.csv
    QString recording;             //!< the positional RECORDING.csv to replay
};

//! The options, or the exit code to end with now: 0 after help or version, ExitBadUsage after
//! one sentence on stderr. Call it before the QApplication exists (it makes a short-lived one
//! only when Qt's own options must be parsed).
std::variant<TunerOptions, int> readTunerOptions(int argc, char *argv[]);

//! Opens the profile and the recording, sets the hand and the repaint rate, shows the window,
//! connects and starts the bridge as the options ask; what fails is said on stderr, and the
//! window stays (a user can fix it there).
void applyTunerOptions(const TunerOptions &options, MainWindow &window);

} // namespace hatpic
