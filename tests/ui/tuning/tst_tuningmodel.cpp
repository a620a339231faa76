// The window's one tuning, headless: the sync state follows the edited tuning, the device's
// and the pushes' outcomes; comparisons are made as the device holds the values (float32);
// a push sends each block the device has and does not hold yet; a refusal names its field, a
// push that failed part-way leaves what it applied in force; signals come once per change;
// edits are undo steps that merge within one field's gesture; push() goes only when it may and
// hands its caller the outcome, after the model took it.
#include "tuning/tuningmodel.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace hatpic;
using namespace Qt::StringLiterals;

namespace {

//! The tuning as a device holds it after taking it: each value as its float32.
DeviceParams asDeviceHolds(const DeviceParams &params)
{
    return roundedForWire(params);
}

Outcome done(const DeviceTuning &sent, const DeviceTuning &received)
{
    return {request::Push{sent}, outcome::Done{outcome::ReadBack::Matches}, received};
}

//! Pushes as every caller does (TuningModel::push) and returns what the model asked the link to
//! send.
DeviceTuning startPush(TuningModel &model)
{
    DeviceTuning sent;
    const auto connection = QObject::connect(&model, &TuningModel::pushRequested,
                                             [&sent](const DeviceTuning &send) { sent = send; });
    const bool started = model.push();
    QObject::disconnect(connection);
    if (!started)
        qFatal("startPush: the model refused to push");
    return sent;
}

Tuning editedWith(const TuningModel &model, double kMax)
{
    Tuning t = model.edited();
    t.device.K_max = kMax;
    return t;
}

} // namespace

class TestTuningModel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void syncFollowsTheDeviceAndTheEdits()
    {
        TuningModel model;
        QCOMPARE(model.syncState(), SyncState::NotConnected);
        model.setCanPush(false, QStringLiteral("the legacy protocol cannot carry parameters"));
        QCOMPARE(model.syncText(), QStringLiteral("the legacy protocol cannot carry parameters"));
        model.setCanPush(true);
        QCOMPARE(model.syncState(), SyncState::NotRead);

        // 0.1 has no exact float: the device holds float(0.1), which is "the same".
        model.setEdited(editedWith(model, 0.1));
        model.setDevice({asDeviceHolds(model.edited().device), std::nullopt, std::nullopt});
        QVERIFY(model.device().params->K_max != 0.1);
        QCOMPARE(model.syncState(), SyncState::InSync);
        QVERIFY(!model.differsFromDevice());

        model.setEdited(editedWith(model, 0.3));
        QCOMPARE(model.syncState(), SyncState::Edited);
        QVERIFY(model.differsFromDevice());
        const std::optional<Tuning> reverted = model.revertedToDevice();
        QVERIFY(reverted);
        QCOMPARE(reverted->device.K_max, 0.1); // tidied back to the decimal the user typed

        // Disconnected: the device and what is known of it are forgotten.
        model.setDevice({});
        QCOMPARE(model.syncState(), SyncState::NotRead);
        QVERIFY(!model.revertedToDevice());
        QVERIFY(!model.differsFromDevice());
    }

    void aPushSendsWhatTheDeviceLacks()
    {
        TuningModel model;
        model.setCanPush(true);
        // A device that has told its blocks: while it has not announced them (their
        // capabilities), they are neither compared nor sent.
        model.setDevice({DeviceParams{}, std::nullopt, PassivityParams::off()});
        QCOMPARE(model.syncState(), SyncState::InSync);
        model.setEffectsTracked(true);
        QCOMPARE(model.syncState(), SyncState::NotRead); // its effects not read yet
        DeviceTuning sent = startPush(model);
        QVERIFY(sent.params && sent.effects && !sent.passivity);
        QCOMPARE(model.syncState(), SyncState::Pushing);
        // The device reads back what it holds: each value as the wire carries it.
        const DeviceTuning readBack = model.editedOnWire();
        QVERIFY(model.pushFinished(done(sent, readBack)));
        QCOMPARE(model.syncState(), SyncState::InSync);
        QVERIFY(!model.pushFinished(done(sent, readBack))); // a late answer changes nothing

        // Only what differs goes: the effects are the device's already.
        model.setEdited(editedWith(model, 0.7));
        sent = startPush(model);
        QVERIFY(sent.params && !sent.effects);
        QCOMPARE(sent.params->K_max, 0.7);
    }

    void aRefusalNamesItsFieldUntilTheNextEdit()
    {
        TuningModel model;
        model.setCanPush(true);
        model.setDevice({DeviceParams{}, std::nullopt, std::nullopt});
        model.setEdited(editedWith(model, 0.9));
        const DeviceTuning sent = startPush(model);
        outcome::Refused refused;
        refused.step = CommandKind::SetParams;
        refused.status = v2::AckStatus::OutOfRange;
        refused.field = deviceFieldIndex("K_max");
        QVERIFY(model.pushFinished({request::Push{sent}, refused, {}}));
        QCOMPARE(model.syncState(), SyncState::Rejected);
        QCOMPARE(model.rejectedField(), QStringLiteral("K_max"));
        QVERIFY(!model.syncText().isEmpty());
        model.setEdited(editedWith(model, 0.5));
        QCOMPARE(model.rejectedField(), QString());
        QCOMPARE(model.syncState(), SyncState::Edited);
    }

    void aPushStoppedPartWayLeavesWhatItApplied()
    {
        TuningModel model;
        model.setCanPush(true);
        model.setEffectsTracked(true);
        model.setDevice({DeviceParams{}, EffectParams{}, std::nullopt});
        Tuning t = editedWith(model, 0.8);
        t.effects.detent_strength = 0.05;
        model.setEdited(t);
        const DeviceTuning sent = startPush(model);
        QVERIFY(sent.params && sent.effects);
        outcome::TimedOut timedOut;
        timedOut.step = CommandKind::SetEffects;
        timedOut.applied = {sent.params, std::nullopt, std::nullopt};
        QSignalSpy device(&model, &TuningModel::deviceChanged);
        QVERIFY(model.pushFinished({request::Push{sent}, timedOut, {}}));
        QCOMPARE(model.syncState(), SyncState::Timeout);
        QCOMPARE(device.count(), 1);
        QCOMPARE(model.device().params->K_max, 0.8);            // in force
        QCOMPARE(model.device().effects->detent_strength, 0.0); // not
        QVERIFY(model.differsFromDevice());
    }

    void aPushTellsItsCallerTheOutcome()
    {
        TuningModel model;
        std::vector<SyncState> heard;
        const auto listen = [&model, &heard](const Outcome &) {
            heard.push_back(model.syncState());
        };
        QSignalSpy requested(&model, &TuningModel::pushRequested);
        QVERIFY(!model.mayPush()); // nothing takes it
        QVERIFY(!model.push(listen));
        model.setCanPush(true);
        model.setDevice({DeviceParams{}, std::nullopt, std::nullopt});

        // An invalid tuning is not pushed, and says why.
        Tuning broken = model.edited();
        broken.device.K_min = broken.device.K_max + 1;
        model.setEdited(broken);
        QVERIFY(!model.violations().empty());
        QCOMPARE(model.violations().front().field, std::string("K_min"));
        QVERIFY(!model.push(listen));
        QCOMPARE(requested.count(), 0);

        // A valid one goes once; a second push waits for the first.
        model.setEdited(editedWith(model, 0.6));
        Tuning valid = model.edited();
        valid.device.K_min = DeviceParams{}.K_min;
        model.setEdited(valid);
        QVERIFY(model.push(listen));
        QCOMPARE(requested.count(), 1);
        QVERIFY(!model.push(listen));
        QCOMPARE(requested.count(), 1);
        const auto sent = requested.at(0).at(0).value<DeviceTuning>();
        QCOMPARE(sent.params->K_max, 0.6);
        QVERIFY(heard.empty());
        // The caller hears once, with the model already in sync.
        QVERIFY(model.pushFinished(done(sent, {asDeviceHolds(*sent.params), std::nullopt})));
        QCOMPARE(heard, std::vector{SyncState::InSync});
        QVERIFY(!model.pushFinished(done(sent, {}))); // late: nobody hears again
        QCOMPARE(heard.size(), std::size_t(1));

        // A push a disconnect dropped still tells its caller its outcome.
        model.setEdited(editedWith(model, 0.7));
        QVERIFY(model.push(listen));
        model.setCanPush(false);
        QVERIFY(!model.pushFinished(
            {request::Push{sent}, outcome::Cut{{}, outcome::Cut::Why::ConnectionLost}, {}}));
        QCOMPARE(heard, (std::vector{SyncState::InSync, SyncState::NotConnected}));
    }

    void signalsComeOncePerChange()
    {
        TuningModel model;
        QSignalSpy edited(&model, &TuningModel::editedChanged);
        QSignalSpy sync(&model, &TuningModel::syncChanged);
        model.setEdited(model.edited()); // the same: nothing
        QCOMPARE(edited.count(), 0);
        Tuning t = model.edited();
        t.host.v_max = 2.5;
        model.setEdited(t);
        QCOMPARE(edited.count(), 1);
        const auto change = edited.at(0).at(0).value<TuningChange>();
        QVERIFY(change.host && !change.device && !change.effects && !change.passivity);
        QCOMPARE(sync.count(), 0); // still not connected, in the same words
        model.setCanPush(true);
        QCOMPARE(sync.count(), 1);
        QCOMPARE(sync.at(0).at(0).value<SyncState>(), SyncState::NotRead);
    }

    void editsAreUndoStepsMergedWithinAGesture()
    {
        TuningModel model;
        QUndoStack undo;
        const double start = model.edited().device.K_max;
        model.edit(undo, model.edited(), u"nothing"_s, u"K_max"_s, 1); // the same: no step
        QCOMPARE(undo.count(), 0);
        // One drag of K_max: three values, one step named after the last.
        for (const double k : {0.5, 0.6, 0.7})
            model.edit(undo, editedWith(model, k), u"K_max %1"_s.arg(k), u"K_max"_s, 1);
        QCOMPARE(undo.count(), 1);
        QCOMPARE(undo.text(0), u"K_max 0.7"_s);
        QCOMPARE(model.edited().device.K_max, 0.7);
        // The next gesture, and a whole tuning (no field), are steps of their own.
        model.edit(undo, editedWith(model, 0.8), u"K_max 0.8"_s, u"K_max"_s, 2);
        model.edit(undo, editedWith(model, 0.9), u"profile"_s);
        model.edit(undo, editedWith(model, 1.0), u"profile"_s);
        QCOMPARE(undo.count(), 4);
        undo.undo();
        undo.undo();
        undo.undo();
        QCOMPARE(model.edited().device.K_max, 0.7);
        undo.undo();
        QCOMPARE(model.edited().device.K_max, start);
        undo.redo();
        QCOMPARE(model.edited().device.K_max, 0.7);
        // A drag back to where it started leaves nothing to undo.
        QUndoStack back;
        model.edit(back, editedWith(model, 0.75), u"K_max"_s, u"K_max"_s, 3);
        model.edit(back, editedWith(model, 0.7), u"K_max"_s, u"K_max"_s, 3);
        QCOMPARE(back.count(), 0);
    }
};

QTEST_GUILESS_MAIN(TestTuningModel)
#include "tst_tuningmodel.moc"
