#include "experimentspanel.h"

#include "experiment/experimentcsv.h"
#include "experiment/experimentrunner.h"
#include "experimentplots.h"
#include "plots/plotpanel.h"
#include "plots/samplebuffer.h"
#include "session/deviceclient.h"

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
#include <QTableWidget>
#include <QVBoxLayout>

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

ExperimentsPanel::ExperimentsPanel(DeviceClient *client, PlotPanel *plots, QWidget *parent)
    : QWidget(parent), m_client(client), m_mainPlots(plots),
      m_runner(new ExperimentRunner(*client, this))
{
    buildForm();
    connect(m_runner, &ExperimentRunner::progress, this,
            [this](double f) { m_progress->setValue(static_cast<int>(std::lround(100 * f))); });
    connect(m_runner, &ExperimentRunner::finished, this, &ExperimentsPanel::onFinished);
    connect(m_client, &DeviceClient::stateChanged, this, &ExperimentsPanel::updateButtons);
    connect(m_client, &DeviceClient::deviceParamsChanged, this, [this] {
        if (!running() && !m_result)
            fillDefaults();
    });
    onKindChanged(); // enables the kind's fields and fills its defaults
    updateButtons();
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

    auto *form = new QFormLayout;
    form->addRow(tr("Experiment"), m_kind);
    form->addRow(tr("τ_ext before the step"), m_from);
    form->addRow(tr("τ_ext after the step"), m_to);
    form->addRow(tr("Bias τ_ext"), m_offset);
    form->addRow(tr("Sine amplitude"), m_amplitude);
    form->addRow(tr("Frequencies [Hz]"), m_frequencies);
    form->addRow(tr("Periods per frequency"), m_cycles);
    form->addRow(tr("Settle"), m_settle);
    form->addRow(tr("Duration"), m_duration);

    m_defaults = new QPushButton(tr("Defaults"), this);
    m_defaults->setToolTip(tr("Levels that keep the knob in the notch band, for the device's "
                              "parameters."));
    m_run = new QPushButton(tr("Run"), this);
    m_run->setObjectName(QStringLiteral("runExperiment"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("cancelExperiment"));
    m_visible = new QPushButton(tr("Spectrum of the visible window"), this);
    m_csv = new QPushButton(tr("Export CSV…"), this);
    m_image = new QPushButton(tr("Export image…"), this);
    auto *buttons = new QHBoxLayout;
    for (QPushButton *b : {m_defaults, m_run, m_cancel})
        buttons->addWidget(b);
    auto *exports = new QHBoxLayout;
    for (QPushButton *b : {m_visible, m_csv, m_image})
        exports->addWidget(b);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 100);
    m_status = new QLabel(tr("Let go of the knob while an experiment runs."), this);
    m_status->setObjectName(QStringLiteral("experimentStatus"));
    m_status->setWordWrap(true);

    m_figures = new QTableWidget(0, 3, this);
    m_figures->setObjectName(QStringLiteral("experimentFigures"));
    m_figures->setHorizontalHeaderLabels({tr("Figure"), tr("Measured"), tr("Model")});
    m_figures->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_figures->verticalHeader()->hide();
    m_figures->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_plots = new ExperimentPlots(this);

    auto *controls = new QWidget(this);
    auto *left = new QVBoxLayout(controls);
    left->addLayout(form);
    left->addLayout(buttons);
    left->addWidget(m_progress);
    left->addWidget(m_status);
    left->addWidget(m_figures, 1);
    left->addLayout(exports);
    // The controls scroll rather than set the dock's width: it sits beside the simulated
    // hand under the plots and must fit there at 1400 px.
    auto *controlsScroll = new QScrollArea(this);
    controlsScroll->setWidgetResizable(true);
    controlsScroll->setFrameShape(QFrame::NoFrame);
    controlsScroll->setWidget(controls);
    controlsScroll->setMinimumWidth(200);
    auto *split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(controlsScroll);
    split->addWidget(m_plots);
    split->setStretchFactor(1, 1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(split);

    connect(m_kind, &QComboBox::currentIndexChanged, this, &ExperimentsPanel::onKindChanged);
    connect(m_defaults, &QPushButton::clicked, this, &ExperimentsPanel::fillDefaults);
    connect(m_run, &QPushButton::clicked, this, &ExperimentsPanel::run);
    connect(m_cancel, &QPushButton::clicked, this, &ExperimentsPanel::cancel);
    connect(m_visible, &QPushButton::clicked, this, &ExperimentsPanel::showVisibleSpectrum);
    connect(m_csv, &QPushButton::clicked, this, &ExperimentsPanel::saveCsvAs);
    connect(m_image, &QPushButton::clicked, this, &ExperimentsPanel::saveImageAs);
    m_visible->setEnabled(m_mainPlots != nullptr);
}

void ExperimentsPanel::onKindChanged()
{
    const auto kind = ExperimentKind(m_kind->currentData().toInt());
    const bool step = kind == ExperimentKind::Step;
    const bool sine = kind == ExperimentKind::Frequency;
    for (QWidget *w : {static_cast<QWidget *>(m_from), static_cast<QWidget *>(m_to)})
        w->setEnabled(step);
    for (QWidget *w : {static_cast<QWidget *>(m_offset), static_cast<QWidget *>(m_amplitude),
                       static_cast<QWidget *>(m_frequencies), static_cast<QWidget *>(m_cycles)})
        w->setEnabled(sine);
    m_duration->setEnabled(!sine);
    fillDefaults();
}

void ExperimentsPanel::fillDefaults()
{
    const ExperimentPlan p = ExperimentPlan::defaults(ExperimentKind(m_kind->currentData().toInt()),
                                                      m_client->deviceParams());
    m_from->setValue(p.tauFrom);
    m_to->setValue(p.tauTo);
    m_offset->setValue(p.offset);
    m_amplitude->setValue(p.amplitude);
    m_settle->setValue(p.settle);
    m_duration->setValue(p.duration);
    QStringList f;
    for (double v : p.frequencies)
        f.append(QString::number(v, 'g', 3));
    m_frequencies->setText(f.join(QStringLiteral(", ")));
    m_cycles->setValue(p.cycles);
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
    m_status->setText(tr("Running… let go of the knob."));
    updateButtons();
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
    if (!result.completed()) {
        m_status->setText(result.problem);
        return;
    }
    m_result = result;
    m_status->setText(result.problem.isEmpty() ? tr("Done; τ_ext is back to 0.") : result.problem);
    showFigures(result);
    m_plots->showResult(result);
    updateButtons();
    Q_EMIT finished(result);
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
    m_figures->setRowCount(static_cast<int>(rows.size()));
    for (int i = 0; i < rows.size(); ++i) {
        m_figures->setItem(i, 0, new QTableWidgetItem(rows[i].name));
        m_figures->setItem(i, 1, new QTableWidgetItem(cell(rows[i].measured, rows[i].decimals)));
        m_figures->setItem(i, 2, new QTableWidgetItem(cell(rows[i].model, rows[i].decimals)));
    }
}

void ExperimentsPanel::updateButtons()
{
    const bool busy = running();
    m_run->setEnabled(!busy && m_client->state() == SessionState::Connected);
    m_cancel->setEnabled(busy);
    m_kind->setEnabled(!busy);
    m_defaults->setEnabled(!busy);
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
