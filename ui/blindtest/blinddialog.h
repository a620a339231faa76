// The blind A/B test's window, thin over BlindRunner: a setup page (trials, seed, question,
// trials file), then a page that says only "trial n of N, interval 1 or 2" and what to press
// (no slot names, no parameter values, no curves), then the result for the experimenter.
// Keys while running: Space goes on to interval 2, 1 or 2 answers, Escape stops.
#pragma once

#include <QDialog>
#include <QMessageBox>

#include <functional>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QStackedWidget;

namespace hatpic {

class BlindRunner;

class BlindDialog : public QDialog
{
    Q_OBJECT
public:
    //! Answers "replace the existing file X?" with Yes or No. Replaceable for tests.
    using Question = std::function<QMessageBox::StandardButton(const QString &text)>;

    BlindDialog(BlindRunner *runner, QWidget *parent = nullptr);

    void setQuestion(Question question) { m_question = std::move(question); }
    //! Shows the setup page with the runner's readiness and a file name to start from.
    void prepare(const QString &suggestedFile);
    //! Start as if pressed: false when the study did not start (the page says why).
    bool startStudy();
    //! Resume as if pressed (a stopped study with trials left): false when it did not go on.
    bool resumeStudy();

protected:
    void keyPressEvent(QKeyEvent *event) override;
    void reject() override;

private:
    void showPhase();
    void chooseFile();

    BlindRunner *m_runner;
    Question m_question;
    QStackedWidget *m_pages = nullptr;
    QSpinBox *m_trials = nullptr;
    QSpinBox *m_seed = nullptr;
    QComboBox *m_questionText = nullptr;
    QLineEdit *m_file = nullptr;
    QLabel *m_setupMessage = nullptr;
    QPushButton *m_start = nullptr;
    QLabel *m_trialLabel = nullptr;
    QLabel *m_intervalLabel = nullptr;
    QLabel *m_prompt = nullptr;
    QLabel *m_result = nullptr;
    QPushButton *m_resume = nullptr;
};

} // namespace hatpic
