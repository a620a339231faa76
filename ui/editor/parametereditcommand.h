// One undoable change of the edited tuning (parameters, host settings, effects). Consecutive
// edits of the same field within one typing or dragging gesture merge into a single undo step.
#pragma once

#include "tuning/tuning.h"

#include <QString>
#include <QUndoCommand>

namespace hatpic {

class ParameterEditor;

class ParameterEditCommand : public QUndoCommand
{
public:
    static constexpr int kMergeId = 0x4854; //!< 'HT'

    //! `field` names the single edited field ("K_max", "wall_max"); empty for whole-set
    //! changes, which never merge. Edits merge only when `gesture` (the editor's gesture
    //! counter) matches.
    ParameterEditCommand(ParameterEditor *editor, const Tuning &before, const Tuning &after,
                         const QString &text, const QString &field = {}, quint64 gesture = 0);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    ParameterEditor *m_editor;
    Tuning m_before;
    Tuning m_after;
    QString m_field;
    quint64 m_gesture;
};

} // namespace hatpic
