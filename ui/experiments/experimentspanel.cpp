#include "experimentspanel.h"

#include "experiment/experimentcsv.h"
#include "experiment/experimentrunner.h"
#include "experiment/operatingpoint.h"
#include "experimentplots.h"
#include "plots/plotpanel.h"
#include "plots/samplebuffer.h"
#include "session/deviceclient.h"

#include <QColor>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QStyle>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hatpic {

namespace {

//! A torque [N·m] or time [s] field of the form.
struct SpinSpec
{
    const char *name;
    double low, high;
    int decimals;
    bool torque; //!< else a time
};

QString cell(double value, int decimals)
{
    return std::isfinite(value) ? QString::number(value, 'f', decimals) : QStringLiteral("–");
}

} // namespace

ExperimentsPanel::ExperimentsPanel(DeviceClient *client, SimulatedJoystick *simulator,
                                   PlotPanel *plots, QWidget *parent)
    : QWidget(parent), m_client(client), m_mainPlots(plots),
      m_runner(new ExperimentRunner(*client, simulator, this))
{
    buildForm();
    connect(m_runner, &ExperimentRunner::progress, this,
            [this](double f) { m_progress->setValue(static_cast<int>(std::lround(100 * f))); });
    connect(m_runner, &ExperimentRunner::finished, this, &ExperimentsPanel::onFinished);
    connect(m_client, &DeviceClient::stateChanged, this, &ExperimentsPanel::updateButtons);
    connect(m_client, &DeviceClient::deviceInfoChanged, this, [this] {
        if (!running() && !m_result)
            showReadyHint();
    });
    // The levels follow the device's tuning, after a run as before it (issue 27: they froze
    // after the first run, and the next one left the notch band); the fields the user typed
    // are kept until Defaults.
    connect(m_client, &DeviceClient::deviceTuningChanged, this, [this] {
        if (!running())
            refreshDefaults();
        if (!running() && !m_result)
            showReadyHint(); // the effects' caution
    });
    onKindChanged(); // shows the kind's fields and fills its defaults
    showReadyHint();
    updateButtons();
}

void ExperimentsPanel::showReadyHint()
{
    const QString hand = m_runner->handFor() == RunHand::SimulatedIdle
                             ? tr("The simulated hand is idle while an experiment runs.")
                             : tr("Let go of the knob while an experiment runs.");
    m_status->setText(
        withCaution(hand, operatingPointWarnings(currentKind(), m_client->deviceTuning())));
}

ExperimentKind ExperimentsPanel::currentKind() const
{
    return ExperimentKind(m_kind->currentData().toInt());
}

QString ExperimentsPanel::withCaution(const QString &text, const QStringList &cautions)
{
    if (cautions.isEmpty())
        return text;
    return text + u'\n' + tr("Caution: %1").arg(cautions.join(u' '));
}

ExperimentsPanel::~ExperimentsPanel() = default;

void ExperimentsPanel::buildForm()
{
    m_kind = new QComboBox(this);
    m_kind->setObjectName(QStringLiteral("experimentKind"));
    m_kind->addItem(tr("Step response"), int(ExperimentKind::Step));
    m_kind->addItem(tr("Frequency response (Bode)"), int(ExperimentKind::Frequency));
    m_kind->addItem(tr("Spectrum at rest"), int(ExperimentKind::Spectrum));
    const std::pair<QDoubleSpinBox **, SpinSpec> spins[] = {
        {&m_from, {"stepFrom", -10, 10, 5, true}},
        {&m_to, {"stepTo", -10, 10, 5, true}},
        {&m_offset, {"sineOffset", -10, 10, 5, true}},
        {&m_amplitude, {"sineAmplitude", 0, 10, 5, true}},
        {&m_settle, {"settle", 0, ExperimentPlan::kMaxDuration, 2, false}},
        {&m_duration, {"duration", 0.01, ExperimentPlan::kMaxDuration, 2, false}},
    };
    for (const auto &[field, spec] : spins) {
        *field = new QDoubleSpinBox(this);
        (*field)->setObjectName(QLatin1String(spec.name));
        (*field)->setRange(spec.low, spec.high);
        (*field)->setDecimals(spec.decimals);
        (*field)->setSingleStep(std::pow(10.0, 1 - spec.decimals));
        (*field)->setSuffix(spec.torque ? QStringLiteral(" N·m") : QStringLiteral(" s"));
    }
    m_frequencies = new QLineEdit(this);
    m_frequencies->setObjectName(QStringLiteral("frequencies"));
    m_frequencies->setToolTip(tr("Ascending frequencies in Hz, separated by commas."));
    m_cycles = new QSpinBox(this);
    m_cycles->setObjectName(QStringLiteral("cycles"));
    m_cycles->setRange(1, ExperimentPlan::kMaxCycles);

    m_form = new QFormLayout;
    m_form->addRow(tr("τ_ext before the step"), m_from);
    m_form->addRow(tr("τ_ext after the step"), m_to);
    m_form->addRow(tr("Bias τ_ext"), m_offset);
    m_form->addRow(tr("Sine amplitude"), m_amplitude);
    m_form->addRow(tr("Frequencies [Hz]"), m_frequencies);
    m_form->addRow(tr("Periods per frequency"), m_cycles);
    m_form->addRow(tr("Settle"), m_settle);
    m_form->addRow(tr("Duration"), m_duration);

    m_defaults = new QPushButton(tr("Defaults"), this);
    m_defaults->setToolTip(tr("Levels that keep the knob in the notch band, for the device's "
                              "parameters."));
    m_run = new QPushButton(tr("Run"), this);
    m_run->setObjectName(QStringLiteral("runExperiment"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("cancelExperiment"));
    m_visible = new QPushButton(tr("Spectrum of the visible window"), this);
    m_visible->setToolTip(tr("The spectra of θ and τ over what the main plots show now"));
    m_csv = new QPushButton(tr("Export CSV…"), this);
    m_image = new QPushButton(tr("Export image…"), this);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 100);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("experimentStatus"));
    m_status->setWordWrap(true);

    m_figures = new QTableWidget(0, 3, this);
    m_figures->setObjectName(QStringLiteral("experimentFigures"));
    m_figures->setHorizontalHeaderLabels({tr("Figure"), tr("Measured"), tr("Model")});
    m_figures->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    for (int column : {1, 2})
        m_figures->horizontalHeader()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
    m_figures->verticalHeader()->hide();
    m_figures->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    m_figures->setWordWrap(false); // one line a figure: more of them in a short dock
    m_figures->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_plots = new ExperimentPlots(this);

    // Three columns, each as tall as the dock: the controls (the kind, Run and the status always
    // in sight; only the kind's fields scroll), the plots, the figures. Issue 21: at 1280×720
    // Run was once hidden in a scrolled column, and the plots were too short to read.
    auto *buttons = new QHBoxLayout;
    for (QPushButton *b : {m_defaults, m_run, m_cancel})
        buttons->addWidget(b);
    auto *fields = new QWidget(this);
    fields->setLayout(m_form);
    m_form->setContentsMargins(0, 0, 0, 0);
    auto *fieldsScroll = new QScrollArea(this);
    fieldsScroll->setWidgetResizable(true);
    fieldsScroll->setFrameShape(QFrame::NoFrame);
    fieldsScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    fieldsScroll->setWidget(fields);
    auto *controls = new QWidget(this);
    auto *left = new QVBoxLayout(controls);
    left->setContentsMargins(0, 0, 0, 0);
    left->addWidget(m_kind);
    left->addLayout(buttons);
    left->addWidget(m_progress);
    left->addWidget(m_status);
    left->addWidget(fieldsScroll, 1);
    left->addWidget(m_visible);
    controls->setMinimumWidth(
        std::max(fields->sizeHint().width() + style()->pixelMetric(QStyle::PM_ScrollBarExtent),
                 buttons->sizeHint().width()));

    m_results = new QWidget(this);
    m_results->setObjectName(QStringLiteral("experimentResults"));
    auto *right = new QVBoxLayout(m_results);
    right->setContentsMargins(0, 0, 0, 0);
    right->addWidget(m_figures, 1);
    auto *exports = new QHBoxLayout;
    for (QPushButton *b : {m_csv, m_image})
        exports->addWidget(b);
    right->addLayout(exports);
    // Wide enough for the names and both columns of numbers, beside the plots.
    const QFontMetrics metrics = fontMetrics();
    m_results->setMinimumWidth(metrics.horizontalAdvance(tr("Settling time 2 % [s]")) +
                               metrics.horizontalAdvance(runHandText(RunHand::SimulatedIdle)) +
                               metrics.horizontalAdvance(QStringLiteral("−0.00000")) + 48);

    m_split = new QSplitter(Qt::Horizontal, this);
    m_split->addWidget(controls);
    m_split->addWidget(m_plots);
    m_split->setStretchFactor(1, 1);
    m_split->setChildrenCollapsible(false);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_split);
    placeFigures();

    // A field the user changed keeps its value when the device's tuning changes.
    for (QDoubleSpinBox *field : {m_from, m_to, m_offset, m_amplitude, m_settle, m_duration})
        connect(field, &QDoubleSpinBox::valueChanged, this, [this, field] {
            if (!m_filling)
                m_typed.insert(field);
        });
    connect(m_cycles, &QSpinBox::valueChanged, this, [this] {
        if (!m_filling)
            m_typed.insert(m_cycles);
    });
    connect(m_frequencies, &QLineEdit::textEdited, this, [this] { m_typed.insert(m_frequencies); });
    connect(m_kind, &QComboBox::currentIndexChanged, this, &ExperimentsPanel::onKindChanged);
    connect(m_defaults, &QPushButton::clicked, this, &ExperimentsPanel::fillDefaults);
    connect(m_run, &QPushButton::clicked, this, &ExperimentsPanel::run);
    connect(m_cancel, &QPushButton::clicked, this, &ExperimentsPanel::cancel);
    connect(m_visible, &QPushButton::clicked, this, &ExperimentsPanel::showVisibleSpectrum);
    connect(m_csv, &QPushButton::clicked, this, &ExperimentsPanel::saveCsvAs);
    connect(m_image, &QPushButton::clicked, this, &ExperimentsPanel::saveImageAs);
    m_visible->setEnabled(m_mainPlots != nullptr);
}

void ExperimentsPanel::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    placeFigures();
}

void ExperimentsPanel::placeFigures()
{
    // Beside the plots when they keep kMinPlotWidth, else one of their tabs.
    const int controls = m_split->widget(0)->minimumSizeHint().width();
    const bool beside = width() >= controls + kMinPlotWidth + m_results->sizeHint().width() +
                                       2 * m_split->handleWidth();
    const int tab = m_plots->indexOf(m_results);
    if (beside && (tab >= 0 || m_results->parent() != m_split)) {
        if (tab >= 0)
            m_plots->removeTab(tab);
        m_split->addWidget(m_results);
        m_results->show();
        // The plot takes what the controls and the figures leave.
        const int results = m_results->minimumWidth();
        m_split->setSizes(
            {controls, std::max(kMinPlotWidth, width() - controls - results), results});
    } else if (!beside && tab < 0) {
        m_plots->addTab(m_results, tr("Figures"));
    }
}

void ExperimentsPanel::onKindChanged()
{
    const auto kind = ExperimentKind(m_kind->currentData().toInt());
    const bool step = kind == ExperimentKind::Step;
    const bool sine = kind == ExperimentKind::Frequency;
    // Only the kind's own fields are shown: fewer rows, so they fit a short dock.
    for (QWidget *w : {static_cast<QWidget *>(m_from), static_cast<QWidget *>(m_to)})
        m_form->setRowVisible(w, step);
    for (QWidget *w : {static_cast<QWidget *>(m_offset), static_cast<QWidget *>(m_amplitude),
                       static_cast<QWidget *>(m_frequencies), static_cast<QWidget *>(m_cycles)})
        m_form->setRowVisible(w, sine);
    m_form->setRowVisible(m_duration, !sine);
    refreshDefaults();
}

void ExperimentsPanel::fillDefaults()
{
    m_typed.clear();
    refreshDefaults();
}

void ExperimentsPanel::refreshDefaults()
{
    const ExperimentPlan p = ExperimentPlan::defaults(
        currentKind(), m_client->deviceTuning().params.value_or(DeviceParams{}));
    m_filling = true;
    const auto fill = [this](QDoubleSpinBox *field, double value) {
        if (!m_typed.contains(field))
            field->setValue(value);
    };
    fill(m_from, p.tauFrom);
    fill(m_to, p.tauTo);
    fill(m_offset, p.offset);
    fill(m_amplitude, p.amplitude);
    fill(m_settle, p.settle);
    fill(m_duration, p.duration);
    if (!m_typed.contains(m_frequencies)) {
        QStringList f;
        for (double v : p.frequencies)
            f.append(QString::number(v, 'g', 3));
        m_frequencies->setText(f.join(QStringLiteral(", ")));
    }
    if (!m_typed.contains(m_cycles))
        m_cycles->setValue(p.cycles);
    m_filling = false;
}

bool ExperimentsPanel::typed(const QWidget *field) const
{
    return m_typed.contains(field);
}

ExperimentPlan ExperimentsPanel::plan() const
{
    ExperimentPlan p;
    p.kind = ExperimentKind(m_kind->currentData().toInt());
    p.tauFrom = m_from->value();
    p.tauTo = m_to->value();
    p.offset = m_offset->value();
    p.amplitude = m_amplitude->value();
    p.settle = m_settle->value();
    p.duration = m_duration->value();
    for (const QString &item : m_frequencies->text().split(u',', Qt::SkipEmptyParts)) {
        bool ok = false;
        const double f = item.trimmed().toDouble(&ok);
        p.frequencies.append(ok ? f : std::nan("")); // check() names a bad one
    }
    p.cycles = m_cycles->value();
    return p;
}

bool ExperimentsPanel::run()
{
    const QString why = m_runner->start(plan());
    if (!why.isEmpty()) {
        m_status->setText(why);
        return false;
    }
    m_progress->setValue(0);
    m_status->setText(withCaution(m_runner->hand() == RunHand::SimulatedIdle
                                      ? tr("Running… the simulated hand is idle until it ends.")
                                      : tr("Running… let go of the knob."),
                                  operatingPointWarnings(currentKind(), m_client->deviceTuning())));
    updateButtons();
    Q_EMIT runningChanged(true);
    return true;
}

void ExperimentsPanel::cancel()
{
    m_runner->cancel();
}

bool ExperimentsPanel::running() const
{
    return m_runner->running();
}

QString ExperimentsPanel::status() const
{
    return m_status->text();
}

void ExperimentsPanel::onFinished(const ExperimentResult &result)
{
    updateButtons();
    Q_EMIT runningChanged(false);
    if (!result.completed()) {
        m_status->setText(result.problem);
        return;
    }
    m_result = result;
    const QString done = result.hand == RunHand::SimulatedIdle
                             ? tr("Done; τ_ext is back to 0, the simulated hand as it was.")
                             : tr("Done; τ_ext is back to 0.");
    // The headline figures where they are always in sight; the table has them all. When the
    // knob was not where the model's figures apply, the status says so next to them.
    m_status->setText(
        withCaution(result.problem.isEmpty() ? done + u' ' + headline(result) : result.problem,
                    operatingPointCaveats(result)));
    showFigures(result);
    m_plots->showResult(result);
    updateButtons();
    Q_EMIT finished(result);
}

QString ExperimentsPanel::headline(const ExperimentResult &r)
{
    switch (r.plan.kind) {
    case ExperimentKind::Step:
        return tr("ω_n %1 rad/s (model %2), ζ %3 (model %4).")
            .arg(cell(r.fitMeasured.omegaN, 1), cell(r.figures.omega_n, 1),
                 cell(r.fitMeasured.zeta, 3), cell(r.figures.zeta, 3));
    case ExperimentKind::Frequency:
        return tr("Bandwidth %1 Hz (model %2).")
            .arg(cell(r.bandwidth, 2), cell(r.modelBandwidth, 2));
    case ExperimentKind::Spectrum:
        break;
    }
    return {};
}

void ExperimentsPanel::showFigures(const ExperimentResult &r)
{
    struct Row
    {
        QString name;
        double measured;
        double model;
        int decimals;
    };
    QList<Row> rows;
    switch (r.plan.kind) {
    case ExperimentKind::Step:
        rows = {
            {tr("ω_n [rad/s]"), r.fitMeasured.omegaN, r.figures.omega_n, 2},
            {tr("ζ"), r.fitMeasured.zeta, r.figures.zeta, 3},
            {tr("Rise time 10–90 % [s]"), r.stepMeasured.riseTime, r.stepIdeal.riseTime, 4},
            {tr("Overshoot [%]"), 100 * r.stepMeasured.overshoot, 100 * r.stepIdeal.overshoot, 1},
            {tr("Settling time 2 % [s]"), r.stepMeasured.settlingTime, r.stepIdeal.settlingTime, 4},
            {tr("Fit rms residual [rad]"), r.fitMeasured.rmsResidual, std::nan(""), 5}};
        break;
    case ExperimentKind::Frequency:
        rows = {{tr("Bandwidth −3 dB [Hz]"), r.bandwidth, r.modelBandwidth, 2}};
        for (const analysis::FrequencyPoint &p : r.points) {
            const std::complex<double> h = analysis::modelGain(r.params, p.frequency);
            rows.append({tr("|θ/τ_ext| at %1 Hz [dB]").arg(p.frequency, 0, 'g', 3),
                         20 * std::log10(p.magnitude), 20 * std::log10(std::abs(h)), 2});
            rows.append({tr("Phase at %1 Hz [°]").arg(p.frequency, 0, 'g', 3),
                         p.phase * 180 / std::numbers::pi, std::arg(h) * 180 / std::numbers::pi,
                         1});
        }
        break;
    case ExperimentKind::Spectrum: {
        const auto theta = analysis::dominantPeak(r.thetaSpectrum, 2 * r.thetaSpectrum.resolution);
        const auto tau = analysis::dominantPeak(r.tauSpectrum, 2 * r.tauSpectrum.resolution);
        rows = {{tr("Strongest θ line [Hz]"), theta.frequency, std::nan(""), 1},
                {tr("Its level [dB re 1 rad]"), theta.magnitudeDb, std::nan(""), 1},
                {tr("Strongest τ line [Hz]"), tau.frequency, std::nan(""), 1},
                {tr("Its level [dB re 1 N·m]"), tau.magnitudeDb, std::nan(""), 1}};
        break;
    }
    }
    // First, what else held the knob: a pushing hand spoils every figure below.
    m_figures->setRowCount(static_cast<int>(rows.size()) + 1);
    m_figures->setItem(0, 0, new QTableWidgetItem(tr("Hand on the knob")));
    m_figures->setItem(0, 1, new QTableWidgetItem(runHandText(r.hand)));
    m_figures->setItem(0, 2, new QTableWidgetItem(tr("none")));
    // Then whether the knob was where the model's figures apply (the status line says why not).
    int first = 1;
    if (r.plan.kind != ExperimentKind::Spectrum) {
        const bool off = !operatingPointCaveats(r).isEmpty();
        m_figures->insertRow(1);
        m_figures->setItem(1, 0, new QTableWidgetItem(tr("Operating point")));
        auto *measured =
            new QTableWidgetItem(off ? tr("not the model's (see the status)") : tr("in band"));
        if (off)
            measured->setForeground(QColor(0xc0, 0x39, 0x2b));
        m_figures->setItem(1, 1, measured);
        m_figures->setItem(1, 2, new QTableWidgetItem(tr("in band")));
        first = 2;
    }
    for (int i = 0; i < rows.size(); ++i) {
        m_figures->setItem(i + first, 0, new QTableWidgetItem(rows[i].name));
        m_figures->setItem(i + first, 1,
                           new QTableWidgetItem(cell(rows[i].measured, rows[i].decimals)));
        m_figures->setItem(i + first, 2,
                           new QTableWidgetItem(cell(rows[i].model, rows[i].decimals)));
    }
}

void ExperimentsPanel::updateButtons()
{
    const bool busy = running();
    const bool canRun = !busy && m_client->state() == SessionState::Connected;
    // The keyboard stays on the panel's buttons (issue 27: Run, disabled once clicked, handed
    // the focus on to the simulated hand's selector): Run gives it to Cancel, Cancel back.
    const bool onButtons = m_run->hasFocus() || m_cancel->hasFocus();
    if (busy) {
        m_cancel->setEnabled(true);
        if (onButtons)
            m_cancel->setFocus(Qt::OtherFocusReason);
    } else {
        m_run->setEnabled(canRun);
        if (onButtons)
            (canRun ? static_cast<QWidget *>(m_run) : m_kind)->setFocus(Qt::OtherFocusReason);
    }
    m_run->setEnabled(canRun);
    m_cancel->setEnabled(busy);
    m_kind->setEnabled(!busy);
    m_defaults->setEnabled(!busy);
    m_progress->setVisible(busy); // only while it means something: a row more for the fields
    m_csv->setEnabled(m_result.has_value());
    m_image->setEnabled(m_result.has_value() || !busy);
}

void ExperimentsPanel::showVisibleSpectrum()
{
    const SampleBuffer *buffer = m_mainPlots ? m_mainPlots->source() : nullptr;
    if (!buffer || buffer->isEmpty()) {
        m_status->setText(tr("The plots show no samples."));
        return;
    }
    QList<Sample> window;
    const qsizetype last = buffer->upperBound(m_mainPlots->viewEnd());
    for (qsizetype i = buffer->lowerBound(m_mainPlots->viewStart()); i < last; ++i)
        window.append(buffer->sample(i));
    analysis::Spectrum theta, tau;
    spectraOf(window, theta, tau);
    if (theta.frequency.empty()) {
        m_status->setText(tr("Too few samples in the visible window for a spectrum."));
        return;
    }
    m_plots->showSpectra(theta, tau, tr("visible window"));
    m_status->setText(tr("Spectrum of %n samples in the visible window.", nullptr,
                         static_cast<int>(window.size())));
}

bool ExperimentsPanel::exportCsv(const QString &path, QString *error) const
{
    if (!m_result) {
        if (error)
            *error = tr("There is no result to export.");
        return false;
    }
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
        file.write(experimentCsv(*m_result)) < 0 || !file.flush()) {
        if (error)
            *error = tr("Could not write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

bool ExperimentsPanel::exportImage(const QString &path, QString *error) const
{
    return m_plots->exportImage(path, error);
}

void ExperimentsPanel::saveCsvAs()
{
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export the result as CSV"), {}, tr("CSV (*.csv)"));
    QString error;
    if (!path.isEmpty() && !exportCsv(path, &error))
        m_status->setText(error);
}

void ExperimentsPanel::saveImageAs()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the plot"), {},
                                                      tr("PNG (*.png);;SVG (*.svg)"));
    QString error;
    if (!path.isEmpty() && !exportImage(path, &error))
        m_status->setText(error);
}

} // namespace hatpic
