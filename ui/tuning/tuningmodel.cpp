#include "tuning/tuningmodel.h"

#include "session/sessionwording.h"

#include <QUndoStack>

#include <iterator>
#include <utility>

namespace hatpic {

namespace {

//! One undoable change of the edited tuning (TuningModel::edit).
class TuningEdit : public QUndoCommand
{
public:
    static constexpr int kMergeId = 0x4854; //!< 'HT'

    TuningEdit(TuningModel &model, const Tuning &after, const QString &text, const QString &field,
               quint64 gesture)
        : m_model(model), m_before(model.edited()), m_after(after), m_field(field),
          m_gesture(gesture)
    {
        setText(text);
    }
    void undo() override { m_model.setEdited(m_before); }
    void redo() override { m_model.setEdited(m_after); }
    int id() const override { return m_field.isEmpty() ? -1 : kMergeId; }
    bool mergeWith(const QUndoCommand *other) override
    {
        if (other->id() != id())
            return false;
        const auto *next = static_cast<const TuningEdit *>(other);
        if (next->m_field != m_field || next->m_gesture != m_gesture || &next->m_model != &m_model)
            return false;
        m_after = next->m_after;
        setText(next->text());
        // Dragging back to where the gesture started leaves nothing to undo.
        setObsolete(m_after == m_before);
        return true;
    }

private:
    TuningModel &m_model;
    Tuning m_before;
    Tuning m_after;
    QString m_field;
    quint64 m_gesture;
};

} // namespace

TuningModel::TuningModel(QObject *parent) : QObject(parent)
{
    m_syncText = computeText(m_syncState);
}

void TuningModel::setEdited(const Tuning &tuning)
{
    const TuningChange change{tuning.device != m_edited.device, tuning.host != m_edited.host,
                              tuning.effects != m_edited.effects,
                              tuning.passivity != m_edited.passivity};
    if (!change.any())
        return;
    m_edited = tuning;
    m_failure.reset();
    m_rejectedField.clear();
    Q_EMIT editedChanged(change);
    refreshSync();
}

void TuningModel::edit(QUndoStack &undo, const Tuning &tuning, const QString &text,
                       const QString &field, quint64 gesture)
{
    if (tuning != m_edited)
        undo.push(new TuningEdit(*this, tuning, text, field, gesture));
}

void TuningModel::setDevice(const DeviceTuning &device)
{
    m_device = device;
    if (!device.params) {
        m_pushing.reset();
        m_pushed.reset();
        m_failure.reset();
        m_rejectedField.clear();
    } else if (m_failure == SyncState::AwaitingReadback) {
        m_failure.reset(); // read at last
    }
    Q_EMIT deviceChanged(m_device);
    refreshSync();
}

void TuningModel::setCanPush(bool canPush, const QString &reason)
{
    m_canPush = canPush;
    m_cannotPushReason = reason;
    if (!canPush)
        m_pushing.reset();
    refreshSync();
}

template<typename Block>
void TuningModel::setTracked(bool &flag, std::optional<Block> &deviceBlock, bool tracked)
{
    flag = tracked;
    if (!tracked && deviceBlock) { // a block the device does not have is not its
        deviceBlock.reset();
        Q_EMIT deviceChanged(m_device);
    }
    refreshSync();
}

void TuningModel::setEffectsTracked(bool tracked)
{
    setTracked(m_effectsTracked, m_device.effects, tracked);
}

void TuningModel::setPassivityTracked(bool tracked)
{
    setTracked(m_passivityTracked, m_device.passivity, tracked);
}

DeviceTuning TuningModel::counted(const DeviceTuning &tuning) const
{
    return {tuning.params, m_effectsTracked ? tuning.effects : std::nullopt,
            m_passivityTracked ? tuning.passivity : std::nullopt};
}

EffectParams TuningModel::effectsOnWire() const
{
    return roundedForWire(m_edited.effects, m_edited.host.tau_limit);
}

DeviceTuning TuningModel::editedOnWire() const
{
    return counted({m_edited.device, effectsOnWire(), roundedForWire(m_edited.passivity)});
}

bool TuningModel::differsFromDevice() const
{
    const DeviceTuning device = counted(m_device);
    const DeviceTuning edited = editedOnWire(); // has each block the counted device has
    return device.params &&
           (!sameOnWire(*edited.params, *device.params) ||
            (device.effects && !sameOnWire(*edited.effects, *device.effects)) ||
            (device.passivity && !sameOnWire(*edited.passivity, *device.passivity)));
}

std::optional<Tuning> TuningModel::revertedToDevice() const
{
    if (!m_device.params)
        return std::nullopt;
    Tuning t = m_edited;
    t.device = tidyDeviceParams(*m_device.params);
    // The device's float32 blocks, unless they are the edited ones as sent: the default
    // effects' ±π travel as the float just inside π and need no revert.
    if (const auto &fx = m_device.effects; fx && !sameOnWire(effectsOnWire(), *fx))
        t.effects = tidyEffectParams(*fx);
    if (const auto &pc = m_device.passivity; pc && !sameOnWire(m_edited.passivity, *pc))
        t.passivity = tidyPassivityParams(*pc);
    return t;
}

std::vector<Violation> TuningModel::violations() const
{
    std::vector<Violation> all = validate(m_edited.device);
    const auto append = [&all](std::vector<Violation> more) {
        all.insert(all.end(), std::make_move_iterator(more.begin()),
                   std::make_move_iterator(more.end()));
    };
    append(validate(m_edited.host));
    append(validate(m_edited.effects, m_edited.host.tau_limit));
    append(validate(m_edited.passivity));
    return all;
}

bool TuningModel::mayPush() const
{
    return m_canPush && !m_pushing && violations().empty();
}

bool TuningModel::push(std::function<void(const Outcome &)> done)
{
    if (!mayPush())
        return false;
    const DeviceTuning send = startPush();
    m_pushDone = std::move(done);
    Q_EMIT pushRequested(send);
    return true;
}

DeviceTuning TuningModel::startPush()
{
    // A block goes along while the device has it and its read-back is not the edited one.
    const DeviceTuning onWire = editedOnWire();
    DeviceTuning send{m_edited.device, std::nullopt, std::nullopt};
    if (m_effectsTracked && (!m_device.effects || !sameOnWire(*onWire.effects, *m_device.effects)))
        send.effects = m_edited.effects;
    if (m_passivityTracked &&
        (!m_device.passivity || !sameOnWire(m_edited.passivity, *m_device.passivity)))
        send.passivity = m_edited.passivity;
    m_pushing = onWire;
    m_pushed.reset();
    m_failure.reset();
    m_rejectedField.clear();
    refreshSync();
    return send;
}

bool TuningModel::pushFinished(const Outcome &outcome)
{
    // The caller hears the outcome after the model took it, even of a push a disconnect dropped.
    const auto done = std::exchange(m_pushDone, nullptr);
    const bool taken = take(outcome);
    if (done)
        done(outcome);
    return taken;
}

bool TuningModel::take(const Outcome &outcome)
{
    if (!m_pushing)
        return false;
    const DeviceTuning pushed = *m_pushing;
    m_pushing.reset();
    const DeviceTuning before = m_device;
    if (const auto *done = std::get_if<outcome::Done>(&outcome.result)) {
        m_device = m_device.updatedBy(outcome.received);
        m_pushed = pushed;
        if (done->readBack == outcome::ReadBack::Unanswered) {
            m_failure = SyncState::AwaitingReadback;
            m_failureText = tr("pushing… (waiting for the read-back)");
        }
    } else {
        if (const auto *refused = std::get_if<outcome::Refused>(&outcome.result)) {
            m_failure = SyncState::Rejected;
            const std::string_view field = refused->fieldName();
            m_rejectedField = QString::fromLatin1(field.data(), qsizetype(field.size()));
        } else {
            m_failure = std::holds_alternative<outcome::TimedOut>(outcome.result)
                            ? SyncState::Timeout
                            : SyncState::Failed;
        }
        // A push that failed part-way changed the device all the same: what it accepted
        // (its read-back where it came) is the device's now.
        if (const outcome::Stopped *stop = outcome.stopped())
            m_device = m_device.updatedBy(stop->applied);
        m_failureText = SessionWording::commandFailureBrief(outcome);
    }
    if (m_device != before)
        Q_EMIT deviceChanged(m_device);
    refreshSync();
    Q_EMIT pushEnded();
    return true;
}

SyncState TuningModel::computeState() const
{
    if (!m_canPush)
        return SyncState::NotConnected;
    if (m_pushing)
        return SyncState::Pushing;
    if (m_failure)
        return *m_failure;
    if (!m_device.params || (m_effectsTracked && !m_device.effects) ||
        (m_passivityTracked && !m_device.passivity))
        return SyncState::NotRead;
    const DeviceTuning wanted = editedOnWire();
    if (sameOnWire(wanted, counted(m_device)))
        return SyncState::InSync;
    if (m_pushed && sameOnWire(wanted, counted(*m_pushed)))
        return SyncState::ReadbackDiffers;
    return SyncState::Edited;
}

QString TuningModel::computeText(SyncState state) const
{
    switch (state) {
    case SyncState::NotConnected:
        return m_cannotPushReason.isEmpty() ? tr("not connected") : m_cannotPushReason;
    case SyncState::NotRead:
        return tr("device values not read yet");
    case SyncState::Edited:
        return tr("edited — not pushed");
    case SyncState::Pushing:
        return tr("pushing…");
    case SyncState::InSync:
        return tr("in sync");
    case SyncState::ReadbackDiffers:
        return tr("not in sync: the device's read-back differs (see ● markers)");
    case SyncState::AwaitingReadback:
    case SyncState::Rejected:
    case SyncState::Timeout:
    case SyncState::Failed:
        return m_failureText;
    }
    return {};
}

void TuningModel::refreshSync()
{
    const SyncState state = computeState();
    const QString text = computeText(state);
    if (state == m_syncState && text == m_syncText)
        return;
    m_syncState = state;
    m_syncText = text;
    Q_EMIT syncChanged(state, text);
}

} // namespace hatpic
