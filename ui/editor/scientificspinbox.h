// A double spin box for physical values spanning decades (1e-6 … 50): shows significant digits
// instead of fixed decimals, accepts scientific input, and can step relative to the value.
#pragma once

#include <QDoubleSpinBox>

namespace hatpic {

class ScientificSpinBox : public QDoubleSpinBox
{
    Q_OBJECT
public:
    enum class StepMode {
        Fixed,    //!< singleStep() per step, like QDoubleSpinBox
        Relative, //!< one unit of the second significant digit (1e-4 → 1.1e-4)
    };

    explicit ScientificSpinBox(QWidget *parent = nullptr);

    void setStepMode(StepMode mode) { m_stepMode = mode; }
    StepMode stepMode() const { return m_stepMode; }

    //! Significant digits shown (default 6); the value itself keeps full precision.
    void setSignificantDigits(int digits);
    int significantDigits() const { return m_digits; }

    //! A bound that is not a valid value itself (N > 0; f < half the control rate): typed text
    //! beyond it is refused (refused()) instead of being replaced by the bound, which would
    //! stand for a value the user never typed and that breaks the same rule.
    void setExclusiveBounds(bool lower, bool upper);

    void stepBy(int steps) override;
    bool event(QEvent *event) override;
    QString textFromValue(double value) const override;
    double valueFromText(const QString &text) const override;
    QValidator::State validate(QString &input, int &pos) const override;
    void fixup(QString &input) const override;

Q_SIGNALS:
    //! Typed text was outside the range and is replaced by the nearest bound (display units).
    void clamped(double typed, double bound);
    //! Typed text was beyond an exclusive bound: the value stays as it was (display units).
    void refused(double typed, double bound);
    //! Typed text was not a number ("4a.b5c"): the value stays as it was.
    void notANumber(const QString &typed);

private:
    //! Drops binary noise after arithmetic (0.00011000000000000002 → 0.00011).
    static double tidy(double value);

    StepMode m_stepMode = StepMode::Fixed;
    int m_digits = 6;
    bool m_lowerExclusive = false;
    bool m_upperExclusive = false;
};

} // namespace hatpic
