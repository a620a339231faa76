#include "experiments/stabilitymapview.h"

#include "analysis/passivityobserver.h"
#include "tuning/tuningmodel.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMetaObject>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSvgWidget>
#include <QThread>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace hatpic {

namespace {

QDoubleSpinBox *spin(QWidget *parent, const char *name, double low, double high, int decimals,
                     double value, const QString &suffix)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setObjectName(QLatin1String(name));
    box->setRange(low, high);
    box->setDecimals(decimals);
    box->setSingleStep(std::pow(10.0, 1 - decimals));
    box->setValue(value);
    box->setSuffix(suffix);
    return box;
}

} // namespace

StabilityMapView::StabilityMapView(const TuningModel &tuning, QWidget *parent)
    : QWidget(parent), m_tuning(tuning)
{
    m_delays = new QLineEdit(QStringLiteral("0:0.3/7"), this);
    m_delays->setObjectName(QStringLiteral("mapDelays"));
    m_delays->setToolTip(tr("One-way delays in s: numbers separated by commas, FROM:TO:STEP or "
                            "FROM:TO/N (N values)."));
    m_gains = new QLineEdit(QStringLiteral("0.01:0.04/7"), this);
    m_gains->setObjectName(QStringLiteral("mapGains"));
    m_gains->setToolTip(tr("Feedback gains in N·m/N, as the delays."));
    m_hands = new QLineEdit(QStringLiteral("0.05"), this);
    m_hands->setObjectName(QStringLiteral("mapHands"));
    m_hands->setToolTip(tr("The hand's constant torque in N·m, as the delays: one map each "
                           "(0.03:0.1/4 tries four hands)."));
    m_contacts = new QSpinBox(this);
    m_contacts->setObjectName(QStringLiteral("mapContacts"));
    m_contacts->setRange(1, 10);
    m_contacts->setValue(1);
    m_contacts->setPrefix(tr("× "));
    m_contacts->setSuffix(tr(" contacts"));
    m_contacts->setToolTip(tr("How many times the hand pushes, lets go for %1 s and pushes "
                              "again; a cell's colour is its worst contact's.")
                               .arg(teleop::LoopConfig::kRelease));
    m_duration = spin(this, "mapDuration", teleop::LoopResult::kRestWindow, 120, 1, 20, tr(" s"));
    m_duration->setToolTip(
        tr("Virtual time each contact runs; it settles when its last 2 s rest."));
    m_delayInUse = spin(this, "mapDelayInUse", 0, robot::kMaxLinkDelay, 3, 0, tr(" s"));
    m_delayInUse->setToolTip(tr("Your network's one-way delay: marked on the map."));
    m_gainInUse = spin(this, "mapGainInUse", 0, bridge::kMaxFeedbackGain, 4,
                       teleop::LoopConfig{}.feedback.gain, tr(" N·m/N"));
    m_gainInUse->setToolTip(tr("The bridge's feedback gain: marked on the map."));

    auto *form = new QFormLayout;
    form->addRow(tr("Delays [s]"), m_delays);
    form->addRow(tr("Gains [N·m/N]"), m_gains);
    // Hands and their contacts share a row, as the settings in use do: the tab stays as short
    // as before in a 1280×720 window.
    auto *hands = new QHBoxLayout;
    hands->addWidget(m_hands, 1);
    hands->addWidget(m_contacts);
    form->addRow(tr("Hands [N·m]"), hands);
    form->addRow(tr("Run each"), m_duration);
    auto *inUse = new QHBoxLayout;
    inUse->addWidget(m_delayInUse);
    inUse->addWidget(m_gainInUse);
    form->addRow(tr("In use"), inUse);

    m_compute = new QPushButton(tr("Compute map"), this);
    m_compute->setObjectName(QStringLiteral("computeMap"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("cancelMap"));
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 100);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("mapStatus"));
    m_status->setWordWrap(true);
    m_status->setText(tr("The loop of robot.md (a hand pushing the robot against its wall) for "
                         "the tuning you edit: where does contact settle, and how fast?"));

    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_compute);
    buttons->addWidget(m_cancel);
    auto *controls = new QVBoxLayout;
    controls->addLayout(form);
    controls->addLayout(buttons);
    controls->addWidget(m_progress);
    controls->addWidget(m_status, 1);

    m_chart = new QSvgWidget(this);
    m_chart->setObjectName(QStringLiteral("mapChart"));
    m_chart->setMinimumSize(320, 200);

    auto *layout = new QHBoxLayout(this);
    layout->addLayout(controls, 0);
    layout->addWidget(m_chart, 1);

    connect(m_compute, &QPushButton::clicked, this, [this] { compute(); });
    connect(m_cancel, &QPushButton::clicked, this, &StabilityMapView::cancel);
    for (QDoubleSpinBox *box : {m_delayInUse, m_gainInUse})
        connect(box, &QDoubleSpinBox::valueChanged, this, &StabilityMapView::redraw);
    connect(&m_tuning, &TuningModel::editedChanged, this, [this] {
        if (!m_cells.empty() && !computing())
            m_status->setText(tr("The tuning changed since this map: compute it again."));
    });
    updateButtons();
}

StabilityMapView::~StabilityMapView()
{
    m_cancelled = true;
    joinWorker();
}

void StabilityMapView::joinWorker()
{
    if (m_worker.joinable())
        m_worker.join();
}

teleop::MapSpec StabilityMapView::spec(QString *error) const
{
    teleop::MapSpec s;
    const Tuning &t = m_tuning.edited();
    s.base.device = t.device;
    s.base.host = t.host;
    s.base.effects = t.effects;
    s.base.passivity = t.passivity;
    // What the controller buys: off beside as edited.
    if (t.passivity.pc_damping_max > 0)
        s.field = {QStringLiteral("pc_damping_max"), {0.0, t.passivity.pc_damping_max}};
    s.base.duration = m_duration->value();
    s.threads = std::clamp(QThread::idealThreadCount(), 1, teleop::kMaxMapThreads);
    QString why;
    const auto delays = teleop::parseValueList(m_delays->text(), &why);
    if (!delays) {
        if (error)
            *error = tr("Delays: %1.").arg(why);
        return s;
    }
    const auto gains = teleop::parseValueList(m_gains->text(), &why);
    if (!gains) {
        if (error)
            *error = tr("Gains: %1.").arg(why);
        return s;
    }
    const auto hands = teleop::parseValueList(m_hands->text(), &why);
    if (!hands) {
        if (error)
            *error = tr("Hands: %1.").arg(why);
        return s;
    }
    s.delays = *delays;
    s.gains = *gains;
    // One hand is the base's hand: no panel per hand.
    if (hands->size() == 1)
        s.base.hand = {HandInput::Kind::Constant, hands->front()};
    else
        s.hands = *hands;
    s.base.contacts = m_contacts->value();
    if (error)
        *error = teleop::checkSpec(s);
    return s;
}

bool StabilityMapView::compute()
{
    if (computing())
        return false;
    QString error;
    const teleop::MapSpec s = spec(&error);
    if (!error.isEmpty()) {
        m_status->setText(error);
        return false;
    }
    joinWorker(); // a finished one
    m_cancelled = false;
    m_done = false;
    const quint64 generation = ++m_generation;
    m_progress->setValue(0);
    m_status->setText(tr("Computing %n cell(s)…", nullptr, int(s.cellCount())));
    m_shown = s;
    m_worker = std::thread([this, s, generation] {
        std::vector<teleop::MapCell> cells = teleop::runMap(
            s,
            [this](qsizetype done, qsizetype total) {
                QMetaObject::invokeMethod(
                    this, [this, done, total] { onProgress(done, total); }, Qt::QueuedConnection);
            },
            &m_cancelled);
        m_done = true;
        QMetaObject::invokeMethod(
            this,
            [this, generation, cells = std::move(cells)]() mutable {
                onFinished(generation, std::move(cells));
            },
            Qt::QueuedConnection);
    });
    updateButtons();
    return true;
}

void StabilityMapView::cancel()
{
    m_cancelled = true;
}

void StabilityMapView::onProgress(qsizetype done, qsizetype total)
{
    if (total > 0)
        m_progress->setValue(int(100 * done / total));
}

void StabilityMapView::onFinished(quint64 generation, std::vector<teleop::MapCell> cells)
{
    if (generation != m_generation)
        return;
    joinWorker();
    const bool complete = qsizetype(cells.size()) == m_shown.cellCount();
    if (!complete) {
        m_status->setText(tr("Cancelled."));
    } else {
        m_cells = std::move(cells);
        const auto settled = std::count_if(m_cells.begin(), m_cells.end(),
                                           [](const auto &c) { return c.result.settled; });
        const auto dampedAtRest =
            std::count_if(m_cells.begin(), m_cells.end(), [](const teleop::MapCell &c) {
                return std::any_of(c.contacts.begin(), c.contacts.end(), [](const auto &r) {
                    return r.settled &&
                           r.dampedAtRest > analysis::PassivityObserver::kDampedAtRestShare;
                });
            });
        QString text =
            tr("%1 of %2 cells settle within %3 s. Grey, crossed cells keep swinging: there "
               "the contact chatters. Lower the gain, add damping (M_adm) or the passivity "
               "controller (pc_damping_max, right) — what it costs is the settle time's "
               "colour.")
                .arg(settled)
                .arg(m_cells.size())
                .arg(m_shown.base.duration);
        if (dampedAtRest > 0)
            text +=
                u' ' + tr("In %n of them the controller still damps the knob at rest: the loop "
                          "does not rest there on its own, and the knob feels heavier than tuned.",
                          nullptr, int(dampedAtRest));
        m_status->setText(text);
        redraw();
    }
    m_progress->setValue(complete ? 100 : 0);
    updateButtons();
    Q_EMIT finished();
}

void StabilityMapView::redraw()
{
    if (m_cells.empty())
        return;
    // The mark is the map's own setting of the controller, not one edited since it was computed.
    m_svg = teleop::mapSvg(m_cells, m_shown.field.name, m_shown.base.duration,
                           teleop::MapMark{m_delayInUse->value(), m_gainInUse->value(),
                                           m_shown.field.name.isEmpty()
                                               ? NAN
                                               : m_shown.base.passivity.pc_damping_max});
    m_chart->load(m_svg);
}

void StabilityMapView::updateButtons()
{
    m_compute->setEnabled(!computing());
    m_cancel->setEnabled(computing());
}

QString StabilityMapView::status() const
{
    return m_status->text();
}

} // namespace hatpic
