#include "blindtest/blindrunner.h"

#include "profiles/profilecontroller.h"
#include "tuning/tuningmodel.h"

namespace hatpic {

BlindRunner::BlindRunner(ProfileController *profiles, TuningModel *model, QObject *parent)
    : QObject(parent), m_profiles(profiles), m_model(model)
{
    // A push whose read-back went unanswered comes in sync with a later read.
    connect(m_model, &TuningModel::syncChanged, this, [this] {
        if (m_readBackLate)
            onPushed();
    });
}

BlindRunner::~BlindRunner() = default;

bool BlindRunner::isRunning() const
{
    return m_phase == Phase::Preparing || m_phase == Phase::Feeling || m_phase == Phase::Answering;
}

QString BlindRunner::slotProfileName(int slot) const
{
    return m_profiles->slotProfile(slot).name;
}

QString BlindRunner::readiness() const
{
    if (!m_profiles->isSlotUsed(0) || !m_profiles->isSlotUsed(1))
        return tr("Load two profiles first: switch A/B (Ctrl+B) to start B, then change it.");
    if (!m_model->canPush())
        return tr("Connect to a device that takes parameters first.");
    for (int slot : {0, 1}) {
        const Profile p = m_profiles->slotProfile(slot);
        if (!validate(p.device).empty() || !validate(p.host).empty() ||
            !validate(p.effects, p.host.tau_limit).empty())
            return tr("Slot %1's parameters are not valid.").arg(ProfileController::slotName(slot));
    }
    return {};
}

bool BlindRunner::start(const BlindSetup &setup, const QString &csvPath)
{
    if (isRunning())
        return false;
    m_error = readiness();
    if (m_error.isEmpty())
        m_error = BlindStudy::check(setup);
    if (!m_error.isEmpty())
        return false;
    m_study = std::make_unique<BlindStudy>(setup);
    m_path = csvPath;
    m_error = m_study->writeCsv(m_path); // the header: the file is there from the start
    if (!m_error.isEmpty())
        return false;
    m_slotBefore = m_profiles->activeSlot();
    Q_EMIT runningChanged(true);
    present(1);
    return true;
}

bool BlindRunner::canResume() const
{
    return m_phase == Phase::Stopped && m_study && !m_study->isFinished();
}

bool BlindRunner::resume()
{
    if (!canResume())
        return false;
    if (const QString why = readiness(); !why.isEmpty()) {
        m_error = why;
        return false;
    }
    m_slotBefore = m_profiles->activeSlot();
    Q_EMIT runningChanged(true);
    present(1);
    return true;
}

void BlindRunner::present(int interval)
{
    m_interval = interval;
    const BlindTrial *trial = m_study->current();
    // Switched first (which shows the slot as edited), then Preparing: this push's outcome
    // decides.
    m_profiles->activateSlot(trial->order[std::size_t(interval - 1)], false);
    setPhase(Phase::Preparing);
    m_readBackLate = false;
    if (!m_model->push([this](const Outcome &) { onPushed(); }))
        stop(tr("Cannot push: %1").arg(m_model->syncText()));
}

void BlindRunner::onPushed()
{
    if (m_phase != Phase::Preparing)
        return;
    m_readBackLate = false;
    switch (m_model->syncState()) {
    case SyncState::Pushing:
        return;
    case SyncState::AwaitingReadback:
        m_readBackLate = true;
        return;
    case SyncState::InSync:
        if (m_interval == 1) {
            m_study->markPresented(QDateTime::currentDateTimeUtc());
            setPhase(Phase::Feeling);
        } else {
            m_since.start();
            setPhase(Phase::Answering);
        }
        return;
    default:
        stop(tr("The device did not take the parameters: %1").arg(m_model->syncText()));
        return;
    }
}

void BlindRunner::next()
{
    if (m_phase == Phase::Feeling)
        present(2);
}

void BlindRunner::answer(int interval)
{
    if (m_phase != Phase::Answering)
        return;
    const double seconds = double(m_since.nsecsElapsed()) * 1e-9;
    if (!m_study->answer(interval, seconds, QDateTime::currentDateTimeUtc()))
        return;
    const QString failure = m_study->writeCsv(m_path);
    if (!failure.isEmpty()) {
        stop(failure);
        return;
    }
    if (m_study->isFinished()) {
        setPhase(Phase::Finished);
        end();
        return;
    }
    present(1);
}

void BlindRunner::abort()
{
    if (isRunning())
        stop(tr("Stopped after %n answered trial(s).", "", m_study->answeredCount()));
}

void BlindRunner::stop(const QString &error)
{
    m_error = error;
    setPhase(Phase::Stopped);
    end();
}

void BlindRunner::end()
{
    // The window shows the slot it showed before; the device keeps the last one presented.
    m_profiles->activateSlot(m_slotBefore, false);
    Q_EMIT runningChanged(false);
}

void BlindRunner::setPhase(Phase phase)
{
    m_phase = phase;
    Q_EMIT phaseChanged(phase);
}

} // namespace hatpic
