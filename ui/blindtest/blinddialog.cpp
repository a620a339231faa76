#include "blindtest/blinddialog.h"

#include "blindtest/blindrunner.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRandomGenerator>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <limits>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

QLabel *bigLabel(const QString &name, double scale, QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setObjectName(name);
    label->setAlignment(Qt::AlignCenter);
    label->setWordWrap(true);
    QFont font = label->font();
    font.setPointSizeF(font.pointSizeF() * scale);
    label->setFont(font);
    return label;
}

} // namespace

BlindDialog::BlindDialog(BlindRunner *runner, QWidget *parent) : QDialog(parent), m_runner(runner)
{
    setObjectName(u"blindDialog"_s);
    setWindowTitle(tr("Blind A/B test"));
    setFocusPolicy(Qt::StrongFocus);
    m_question = [this](const QString &text) {
        return QMessageBox::question(this, tr("Replace file?"), text,
                                     QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
    };

    // Setup: what the experimenter chooses.
    auto *setup = new QWidget(this);
    m_trials = new QSpinBox(setup);
    m_trials->setObjectName(u"blind_trials"_s);
    m_trials->setRange(1, 1000);
    m_trials->setValue(10);
    m_seed = new QSpinBox(setup);
    m_seed->setObjectName(u"blind_seed"_s);
    m_seed->setRange(-1, std::numeric_limits<int>::max());
    m_seed->setSpecialValueText(tr("random"));
    m_seed->setValue(-1);
    m_seed->setToolTip(tr("The same seed gives the same order of A and B; random picks one and "
                          "writes it into the file"));
    m_questionText = new QComboBox(setup);
    m_questionText->setObjectName(u"blind_question"_s);
    m_questionText->setEditable(true);
    m_questionText->addItems({tr("Which felt stiffer?"), tr("Which notch felt stronger?"),
                              tr("Which felt smoother?"), tr("Which felt heavier?")});
    m_file = new QLineEdit(setup);
    m_file->setObjectName(u"blind_file"_s);
    auto *browse = new QPushButton(tr("Browse…"), setup);
    connect(browse, &QPushButton::clicked, this, &BlindDialog::chooseFile);
    auto *fileRow = new QHBoxLayout;
    fileRow->addWidget(m_file, 1);
    fileRow->addWidget(browse);
    auto *form = new QFormLayout;
    form->addRow(tr("Trials:"), m_trials);
    form->addRow(tr("Seed:"), m_seed);
    form->addRow(tr("Question:"), m_questionText);
    form->addRow(tr("Trials file (CSV):"), fileRow);
    auto *how = new QLabel(
        tr("Each trial presents the two profiles one after the other, as interval 1 and "
           "interval 2, in a random order; the participant answers the question with 1 or 2. "
           "The tuner pushes each interval and waits until the device has it. While the test "
           "runs this window fills the screen and shows no names, values or curves. Keys: "
           "Space for interval 2, 1 or 2 to answer, Escape to stop. Every answer is written to "
           "the file at once."),
        setup);
    how->setWordWrap(true);
    m_setupMessage = new QLabel(setup);
    m_setupMessage->setObjectName(u"blind_setup_message"_s);
    m_setupMessage->setWordWrap(true);
    m_start = new QPushButton(tr("Start"), setup);
    m_start->setObjectName(u"blind_start"_s);
    m_start->setDefault(true);
    connect(m_start, &QPushButton::clicked, this, &BlindDialog::startStudy);
    auto *setupLayout = new QVBoxLayout(setup);
    setupLayout->addWidget(how);
    setupLayout->addLayout(form);
    setupLayout->addWidget(m_setupMessage);
    setupLayout->addStretch(1);
    setupLayout->addWidget(m_start, 0, Qt::AlignRight);

    // Running: only the trial, the interval and what to press.
    auto *run = new QWidget(this);
    m_trialLabel = bigLabel(u"blind_trial"_s, 1.5, run);
    m_intervalLabel = bigLabel(u"blind_interval"_s, 4.0, run);
    m_prompt = bigLabel(u"blind_prompt"_s, 1.8, run);
    auto *runLayout = new QVBoxLayout(run);
    runLayout->addStretch(1);
    runLayout->addWidget(m_trialLabel);
    runLayout->addWidget(m_intervalLabel);
    runLayout->addWidget(m_prompt);
    runLayout->addStretch(1);

    // Done: the result, for the experimenter.
    auto *done = new QWidget(this);
    m_result = new QLabel(done);
    m_result->setObjectName(u"blind_result"_s);
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto *close = new QDialogButtonBox(QDialogButtonBox::Close, done);
    connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
    m_resume = close->addButton(tr("Resume"), QDialogButtonBox::ActionRole);
    m_resume->setObjectName(u"blind_resume"_s);
    m_resume->setToolTip(tr("Go on from the first unanswered trial, in the same trials file"));
    connect(m_resume, &QPushButton::clicked, this, &BlindDialog::resumeStudy);
    auto *doneLayout = new QVBoxLayout(done);
    doneLayout->addWidget(m_result, 1);
    doneLayout->addWidget(close);

    m_pages = new QStackedWidget(this);
    m_pages->addWidget(setup);
    m_pages->addWidget(run);
    m_pages->addWidget(done);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_pages);
    resize(560, 420);

    connect(m_runner, &BlindRunner::phaseChanged, this, &BlindDialog::showPhase);
}

void BlindDialog::prepare(const QString &suggestedFile)
{
    if (m_runner->isRunning())
        return;
    // A new file for a new study (the last study's stays as it was written).
    if (m_file->text().isEmpty() || QFileInfo::exists(m_file->text()))
        m_file->setText(suggestedFile);
    const QString readiness = m_runner->readiness();
    m_setupMessage->setText(readiness);
    m_start->setEnabled(readiness.isEmpty());
    m_pages->setCurrentIndex(0);
}

void BlindDialog::chooseFile()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Trials file"), m_file->text(),
                                                      tr("CSV files (*.csv);;All files (*)"),
                                                      nullptr, QFileDialog::DontConfirmOverwrite);
    if (!path.isEmpty())
        m_file->setText(path);
}

bool BlindDialog::startStudy()
{
    QString path = m_file->text().trimmed();
    if (path.isEmpty()) {
        m_setupMessage->setText(tr("Choose a trials file first."));
        return false;
    }
    if (QFileInfo(path).suffix().isEmpty())
        path += u".csv"_s;
    // Never replaces a file the tuner did not write in this study without asking.
    if (QFileInfo::exists(path) &&
        m_question(tr("%1 exists. Replace it with this study's trials?")
                       .arg(QDir::toNativeSeparators(path))) != QMessageBox::Yes) {
        m_setupMessage->setText(tr("Not started: choose another trials file."));
        return false;
    }
    BlindSetup setup;
    setup.trials = m_trials->value();
    setup.seed = m_seed->value() >= 0 ? quint64(m_seed->value())
                                      : QRandomGenerator::system()->bounded(1u << 31);
    setup.question = m_questionText->currentText();
    setup.profileA = m_runner->slotProfileName(0);
    setup.profileB = m_runner->slotProfileName(1);
    m_pages->setCurrentIndex(1);
    if (!m_runner->start(setup, path)) {
        m_pages->setCurrentIndex(0);
        m_setupMessage->setText(m_runner->error());
        return false;
    }
    return true;
}

bool BlindDialog::resumeStudy()
{
    if (!m_runner->resume()) {
        m_result->setText(m_result->text() + u"\n\n"_s +
                          tr("Cannot resume: %1").arg(m_runner->error()));
        return false;
    }
    return true;
}

void BlindDialog::showPhase()
{
    using Phase = BlindRunner::Phase;
    const Phase phase = m_runner->phase();
    const BlindStudy *study = m_runner->study();
    if (phase == Phase::Finished || phase == Phase::Stopped) {
        setWindowState(windowState() & ~Qt::WindowMaximized);
        const BlindStudy::Score s = study->score();
        QString text = phase == Phase::Finished
                           ? tr("Done: all %1 trials answered.").arg(study->trials().size())
                           : m_runner->error();
        text += u"\n\n"_s + tr("Written to %1.").arg(QDir::toNativeSeparators(m_runner->csvPath()));
        if (s.answered > 0) {
            text += u"\n\n"_s +
                    tr("\"%1\": B was chosen in %2 of %3 trials, A in %4 (two-sided binomial "
                       "test against chance: p = %5). Interval 1 was chosen %6 times.")
                        .arg(study->setup().question)
                        .arg(s.chosenB)
                        .arg(s.answered)
                        .arg(s.answered - s.chosenB)
                        .arg(QString::number(s.pValue, 'g', 3))
                        .arg(s.chosenFirst);
        }
        m_result->setText(text);
        m_resume->setVisible(m_runner->canResume());
        m_pages->setCurrentIndex(2);
        return;
    }
    if (phase == Phase::Idle || !study || !study->current())
        return;
    if (!isMaximized())
        setWindowState(windowState() | Qt::WindowMaximized);
    m_pages->setCurrentIndex(1);
    setFocus();
    m_trialLabel->setText(
        tr("Trial %1 of %2").arg(study->current()->number).arg(study->trials().size()));
    m_intervalLabel->setText(tr("Interval %1").arg(m_runner->interval()));
    switch (phase) {
    case Phase::Preparing:
        m_prompt->setText(tr("Please wait…"));
        break;
    case Phase::Feeling:
        m_prompt->setText(tr("Feel the knob, then press Space for interval 2."));
        break;
    case Phase::Answering:
        m_prompt->setText(tr("%1\nPress 1 or 2.").arg(study->setup().question));
        break;
    default:
        break;
    }
}

void BlindDialog::keyPressEvent(QKeyEvent *event)
{
    if (!m_runner->isRunning()) {
        QDialog::keyPressEvent(event);
        return;
    }
    switch (event->key()) {
    case Qt::Key_Space:
        m_runner->next();
        break;
    case Qt::Key_1:
        m_runner->answer(1);
        break;
    case Qt::Key_2:
        m_runner->answer(2);
        break;
    case Qt::Key_Escape:
        m_runner->abort();
        break;
    default:
        break; // no other key does anything while the participant answers
    }
}

void BlindDialog::reject()
{
    m_runner->abort(); // closing the window stops the study; the answered trials are saved
    QDialog::reject();
}

} // namespace hatpic
