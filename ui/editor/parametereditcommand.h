// One undoable change of the edited parameter set. Consecutive edits of the same field within
// one typing or dragging gesture merge into a single undo step.
#pragma once

#include "model/params.h"

#include <QString>
#include <QUndoCommand>

namespace hatpic {

class ParameterEditor;

class ParameterEditCommand : public QUndoCommand
{
public:
    static constexpr int kMergeId = 0x4854; //!< 'HT'

    //! `field` names the single edited field ("K_max"); empty for whole-set changes, which
    //! never merge. Edits merge only when `gesture` (the editor's gesture counter) matches.
    ParameterEditCommand(ParameterEditor *editor, const DeviceParams &beforeDevice,
                         const HostParams &beforeHost, const DeviceParams &afterDevice,
                         const HostParams &afterHost, const QString &text,
                         const QString &field = {}, quint64 gesture = 0);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    ParameterEditor *m_editor;
    DeviceParams m_beforeDevice;
    HostParams m_beforeHost;
    DeviceParams m_afterDevice;
    HostParams m_afterHost;
    QString m_field;
    quint64 m_gesture;
};

} // namespace hatpic
