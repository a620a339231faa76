// A parameter editor as the window makes it: on a tuning model and an undo stack that are not
// its own (the window owns them and hands them to the editor, the link, profiles and the blind
// test). Tests that need an editor hold this instead.
#pragma once

#include "editor/parametereditor.h"
#include "tuning/tuningmodel.h"

#include <QUndoStack>

namespace hatpic::test {

struct EditorRig
{
    TuningModel model;
    QUndoStack undo;
    ParameterEditor editor{&model, &undo}; //!< last: destroyed first
};

} // namespace hatpic::test
