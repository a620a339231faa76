#include "simulator/simulatorpanel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>
#include <numbers>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

using Kind = HandInput::Kind;

QDoubleSpinBox *spinBox(QWidget *parent, const QString &name, double lo, double hi, double step,
                        int decimals, const QString &suffix, const QString &tip)
{
    auto *s = new QDoubleSpinBox(parent);
    s->setObjectName(name);
    s->setRange(lo, hi);
    s->setSingleStep(step);
    s->setDecimals(decimals);
    s->setSuffix(suffix);
    s->setToolTip(tip);
    s->setKeyboardTracking(false);
    s->setLocale(QLocale::c());
    return s;
}

} // namespace

SimulatorPanel::SimulatorPanel(QWidget *parent) : QWidget(parent)
{
    m_kind = new QComboBox(this);
    m_kind->setObjectName(u"combo_hand_kind"_s);
    m_kind->addItem(tr("Idle — hand off the knob"), int(Kind::Idle));
    m_kind->addItem(tr("Constant torque"), int(Kind::Constant));
    m_kind->addItem(tr("Step"), int(Kind::Step));
    m_kind->addItem(tr("Sine"), int(Kind::Sine));
    m_kind->addItem(tr("Chirp (linear sweep)"), int(Kind::Chirp));
    m_kind->addItem(tr("Virtual hand — drag the target"), int(Kind::VirtualHand));
    m_kind->addItem(tr("Pushes — push, let go, again"), int(Kind::Pushes));

    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("handStatus"));
    m_status->hide(); // until the window puts it in its status bar

    m_description = new QLabel(this);
    m_description->setWordWrap(true);
    m_description->setStyleSheet(QStringLiteral("color: gray;"));

    const QString torqueTip = tr("Operator torque τ_op on the knob; positive pushes θ positive "
                                 "(the measured τ is its negative)");
    m_amplitude = spinBox(this, u"spin_hand_amplitude"_s, -kMaxTorque, kMaxTorque, 0.01, 3,
                          u" N·m"_s, torqueTip);
    m_offset = spinBox(this, u"spin_hand_offset"_s, -kMaxTorque, kMaxTorque, 0.01, 3, u" N·m"_s,
                       tr("Torque before the step (T0) [N·m]"));
    m_frequency = spinBox(this, u"spin_hand_frequency"_s, 0, kMaxFrequency, 0.1, 2, u" Hz"_s,
                          tr("Frequency of the sine, or start frequency F0 of the chirp"));
    m_frequency1 = spinBox(this, u"spin_hand_frequency1"_s, 0, kMaxFrequency, 0.1, 2, u" Hz"_s,
                           tr("End frequency F1 of the chirp; one sweep lasts %1 s, then repeats")
                               .arg(HandInput::kChirpPeriod));
    m_angle = spinBox(this, u"spin_hand_angle"_s, -std::numbers::pi / 2, std::numbers::pi / 2, 0.01,
                      3, u" rad"_s,
                      tr("Target angle of the virtual hand: a spring of %1 N·m/rad and a damper "
                         "of %2 N·m·s/rad pull the knob toward it")
                          .arg(HandInput::kHandStiffness)
                          .arg(HandInput::kHandDamping));
    m_pushes = new QSpinBox(this);
    m_pushes->setObjectName(u"spin_hand_pushes"_s);
    m_pushes->setRange(1, HandInput::kMaxPushes);
    m_pushes->setKeyboardTracking(false);
    m_pushes->setToolTip(tr("How many times the hand pushes; then it lets go"));
    m_pushTime = spinBox(this, u"spin_hand_push_time"_s, 0.1, HandInput::kMaxPhase, 1, 1, u" s"_s,
                         tr("How long each push holds the torque T"));
    m_releaseTime = spinBox(this, u"spin_hand_release_time"_s, 0, HandInput::kMaxPhase, 0.5, 1,
                            u" s"_s, tr("How long the hand lets go between two pushes"));
    m_angleSlider = new QSlider(Qt::Horizontal, this);
    m_angleSlider->setObjectName(u"slider_hand_angle"_s);
    const int ticks = int(std::lround(std::numbers::pi / 2 * kAngleTicksPerRad));
    m_angleSlider->setRange(-ticks, ticks);
    m_angleSlider->setToolTip(m_angle->toolTip());
    m_angleDegrees = new QLabel(this);
    m_angleDegrees->setMinimumWidth(m_angleDegrees->fontMetrics().horizontalAdvance(u"-90.0°"_s));

    auto *release = new QPushButton(tr("Let go"), this);
    release->setObjectName(u"button_hand_release"_s);
    release->setToolTip(tr("Take the hand off the knob (idle)"));

    m_amplitudeLabel = new QLabel(tr("Torque T / amplitude A"), this);
    m_offsetLabel = new QLabel(tr("Torque before the step T0"), this);
    m_frequencyLabel = new QLabel(tr("Frequency F / F0"), this);
    m_frequency1Label = new QLabel(tr("End frequency F1"), this);
    m_angleLabel = new QLabel(tr("Target angle"), this);
    m_pushesLabel = new QLabel(tr("Pushes N"), this);
    m_pushTimeLabel = new QLabel(tr("Each push"), this);
    m_releaseTimeLabel = new QLabel(tr("Let go between"), this);

    auto *angleRow = new QHBoxLayout;
    angleRow->addWidget(m_angleSlider, 1);
    angleRow->addWidget(m_angle);
    angleRow->addWidget(m_angleDegrees);

    auto *form = new QFormLayout;
    form->setLabelAlignment(Qt::AlignRight);
    auto *kindRow = new QHBoxLayout;
    kindRow->addWidget(m_kind, 1);
    kindRow->addWidget(release);
    form->addRow(tr("Hand input"), kindRow);
    form->addRow(m_amplitudeLabel, m_amplitude);
    form->addRow(m_offsetLabel, m_offset);
    form->addRow(m_frequencyLabel, m_frequency);
    form->addRow(m_frequency1Label, m_frequency1);
    form->addRow(m_angleLabel, angleRow);
    form->addRow(m_pushesLabel, m_pushes);
    form->addRow(m_pushTimeLabel, m_pushTime);
    form->addRow(m_releaseTimeLabel, m_releaseTime);

    m_inputs = new QWidget(this);
    m_inputs->setLayout(form);
    form->setContentsMargins(0, 0, 0, 0);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_inputs);
    layout->addWidget(m_description);
    layout->addStretch(1);

    m_amplitude->setValue(0.05);
    m_offset->setValue(0.0);
    m_frequency->setValue(1.0);
    m_frequency1->setValue(10.0);
    m_pushes->setValue(3);
    m_pushTime->setValue(10.0);
    m_releaseTime->setValue(2.0);

    connect(m_kind, &QComboBox::currentIndexChanged, this, [this] {
        updateVisibility();
        emitIfChanged();
    });
    for (QDoubleSpinBox *s :
         {m_amplitude, m_offset, m_frequency, m_frequency1, m_pushTime, m_releaseTime})
        connect(s, &QDoubleSpinBox::valueChanged, this, &SimulatorPanel::emitIfChanged);
    connect(m_pushes, &QSpinBox::valueChanged, this, &SimulatorPanel::emitIfChanged);
    connect(m_angle, &QDoubleSpinBox::valueChanged, this, [this](double rad) {
        const QSignalBlocker block(m_angleSlider);
        m_angleSlider->setValue(int(std::lround(rad * kAngleTicksPerRad)));
        emitIfChanged();
    });
    connect(m_angleSlider, &QSlider::valueChanged, this, [this](int tick) {
        const QSignalBlocker block(m_angle);
        m_angle->setValue(double(tick) / kAngleTicksPerRad);
        emitIfChanged();
    });
    connect(release, &QPushButton::clicked, this,
            [this] { m_kind->setCurrentIndex(m_kind->findData(int(Kind::Idle))); });

    updateVisibility();
    m_last = hand();
}

HandInput SimulatorPanel::hand() const
{
    HandInput h;
    h.kind = static_cast<Kind>(m_kind->currentData().toInt());
    switch (h.kind) {
    case Kind::Idle:
        break;
    case Kind::Constant:
        h.amplitude = m_amplitude->value();
        break;
    case Kind::Step:
        h.amplitude = m_amplitude->value();
        h.offset = m_offset->value();
        break;
    case Kind::Sine:
        h.amplitude = m_amplitude->value();
        h.frequency = m_frequency->value();
        break;
    case Kind::Chirp:
        h.amplitude = m_amplitude->value();
        h.frequency = m_frequency->value();
        h.frequency1 = m_frequency1->value();
        break;
    case Kind::VirtualHand:
        h.angle = m_angle->value();
        break;
    case Kind::Pushes:
        h = HandInput::pushing(m_amplitude->value(), m_pushes->value(), m_pushTime->value(),
                               m_releaseTime->value());
        break;
    }
    return h;
}

void SimulatorPanel::setHand(const HandInput &hand)
{
    {
        const QSignalBlocker b0(m_kind);
        const QSignalBlocker b1(m_amplitude);
        const QSignalBlocker b2(m_offset);
        const QSignalBlocker b3(m_frequency);
        const QSignalBlocker b4(m_frequency1);
        const QSignalBlocker b5(m_angle);
        const QSignalBlocker b6(m_angleSlider);
        const QSignalBlocker b7(m_pushes);
        const QSignalBlocker b8(m_pushTime);
        const QSignalBlocker b9(m_releaseTime);
        m_kind->setCurrentIndex(m_kind->findData(int(hand.kind)));
        // Only the fields this kind uses; the others keep what the user last typed.
        switch (hand.kind) {
        case Kind::Idle:
            break;
        case Kind::Constant:
            m_amplitude->setValue(hand.amplitude);
            break;
        case Kind::Step:
            m_amplitude->setValue(hand.amplitude);
            m_offset->setValue(hand.offset);
            break;
        case Kind::Sine:
            m_amplitude->setValue(hand.amplitude);
            m_frequency->setValue(hand.frequency);
            break;
        case Kind::Chirp:
            m_amplitude->setValue(hand.amplitude);
            m_frequency->setValue(hand.frequency);
            m_frequency1->setValue(hand.frequency1);
            break;
        case Kind::VirtualHand:
            m_angle->setValue(hand.angle);
            m_angleSlider->setValue(int(std::lround(hand.angle * kAngleTicksPerRad)));
            break;
        case Kind::Pushes:
            m_amplitude->setValue(hand.amplitude);
            m_pushes->setValue(hand.pushes);
            m_pushTime->setValue(hand.pushTime);
            m_releaseTime->setValue(hand.releaseTime);
            break;
        }
    }
    updateVisibility();
    m_last = this->hand();
}

QString SimulatorPanel::describe(const HandInput &h)
{
    const auto n = [](double v) { return QString::number(v, 'g', 3); };
    switch (h.kind) {
    case Kind::Idle:
        return tr("Hand: none");
    case Kind::Constant:
        return tr("Hand: constant %1 N·m").arg(n(h.amplitude));
    case Kind::Step:
        return tr("Hand: step %1 → %2 N·m").arg(n(h.offset), n(h.amplitude));
    case Kind::Sine:
        return tr("Hand: sine %1 N·m at %2 Hz").arg(n(h.amplitude), n(h.frequency));
    case Kind::Chirp:
        return tr("Hand: chirp %1 N·m, %2 → %3 Hz")
            .arg(n(h.amplitude), n(h.frequency), n(h.frequency1));
    case Kind::VirtualHand:
        return tr("Hand: virtual hand to %1 rad").arg(n(h.angle));
    case Kind::Pushes:
        return tr("Hand: %1 N·m pushes, %2 × %3 s, %4 s apart")
            .arg(n(h.amplitude), QString::number(h.pushes), n(h.pushTime), n(h.releaseTime));
    }
    return {};
}

void SimulatorPanel::setHeldByExperiment(bool held)
{
    m_held = held;
    m_inputs->setEnabled(!held);
    updateVisibility();
}

void SimulatorPanel::updateVisibility()
{
    m_status->setText(m_held ? tr("Hand: idle for the experiment") : describe(hand()));
    m_status->setToolTip(
        tr("The simulated hand's input (View → Simulated hand): %1").arg(hand().toSpec()));
    const auto kind = static_cast<Kind>(m_kind->currentData().toInt());
    const bool torque = kind != Kind::Idle && kind != Kind::VirtualHand;
    const bool periodic = kind == Kind::Sine || kind == Kind::Chirp;
    const auto show = [](QWidget *label, QWidget *field, bool on) {
        label->setVisible(on);
        field->setVisible(on);
    };
    show(m_amplitudeLabel, m_amplitude, torque);
    show(m_offsetLabel, m_offset, kind == Kind::Step);
    show(m_frequencyLabel, m_frequency, periodic);
    show(m_frequency1Label, m_frequency1, kind == Kind::Chirp);
    show(m_angleLabel, m_angle, kind == Kind::VirtualHand);
    m_angleSlider->setVisible(kind == Kind::VirtualHand);
    m_angleDegrees->setVisible(kind == Kind::VirtualHand);
    for (auto [label, field] : {std::pair<QWidget *, QWidget *>{m_pushesLabel, m_pushes},
                                {m_pushTimeLabel, m_pushTime},
                                {m_releaseTimeLabel, m_releaseTime}})
        show(label, field, kind == Kind::Pushes);
    m_amplitudeLabel->setText(periodic ? tr("Amplitude A") : tr("Torque T"));
    m_frequencyLabel->setText(kind == Kind::Chirp ? tr("Start frequency F0") : tr("Frequency F"));
    m_angleDegrees->setText(tr("%1°").arg(m_angle->value() * 180.0 / std::numbers::pi, 0, 'f', 1));

    QString text;
    switch (kind) {
    case Kind::Idle:
        text = tr("No hand on the knob: it rests where re-centering leaves it.");
        break;
    case Kind::Constant:
        text = tr("A constant torque T pushes the knob.");
        break;
    case Kind::Step:
        text = tr("T0 until %1 s, then T: shows the step response.").arg(HandInput::kStepTime);
        break;
    case Kind::Sine:
        text = tr("A sine torque of amplitude A at frequency F.");
        break;
    case Kind::Chirp:
        text = tr("A sine whose frequency sweeps linearly from F0 to F1 over %1 s, then repeats.")
                   .arg(HandInput::kChirpPeriod);
        break;
    case Kind::VirtualHand:
        text = tr("A hand holding the knob near the target angle (spring %1 N·m/rad, damper "
                  "%2 N·m·s/rad): drag the slider to move it.")
                   .arg(HandInput::kHandStiffness)
                   .arg(HandInput::kHandDamping);
        break;
    case Kind::Pushes:
        text = tr("The same contact again and again: the hand pushes with T, lets go, and "
                  "pushes again, N times; then it lets go.");
        break;
    }
    if (m_held)
        text = tr("Idle while the experiment runs, so that only its τ_ext moves the knob; the "
                  "input below comes back when it ends.");
    m_description->setText(text);
}

void SimulatorPanel::emitIfChanged()
{
    updateVisibility();
    const HandInput h = hand();
    if (h == m_last)
        return;
    m_last = h;
    m_chosen = true;
    Q_EMIT handChanged(h);
}

HandInput SimulatorPanel::gentleHand()
{
    // 0.06 N·m is more than the notch holds with the default parameters (K_max·N = 0.04 N·m),
    // so the knob is pushed out of the notch and back every 5 s: dead zone, notch and slope
    // all show in the plots and on the stiffness curve.
    HandInput hand;
    hand.kind = HandInput::Kind::Sine;
    hand.amplitude = 0.06;
    hand.frequency = 0.2;
    return hand;
}

void SimulatorPanel::chooseHand(const HandInput &hand)
{
    m_chosen = true;
    setHand(hand);
}

HandInput SimulatorPanel::handToStartWith(const HandInput &requested)
{
    HandInput start = requested;
    if (m_chosen)
        start = hand();
    else if (requested.kind == HandInput::Kind::Idle)
        start = gentleHand();
    setHand(start);
    return start;
}

} // namespace hatpic
