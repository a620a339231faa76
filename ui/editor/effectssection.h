// The editor's Effects section (effects.md): the detent and end-stop fields of the device's
// effect block, the figures and warnings that tell whether they will feel right or chatter,
// and a vibration test (VIBRATE) with amplitude, frequency and duration. It holds no tuning:
// the editor owns the values, validates them and puts every edit on its undo stack.
#pragma once

#include "model/effects.h"

#include <QList>
#include <QWidget>

class QLabel;
class QPushButton;

namespace hatpic {

class ParameterField;

class EffectsSection : public QWidget
{
    Q_OBJECT
public:
    //! QSettings keys of the vibration test's last values (SI).
    static constexpr char16_t kVibrationKey[] = u"effects/vibration";
    //! The vibration test's values before any is remembered: a short, clearly felt buzz.
    static constexpr Vibration kDefaultVibration{0.05, 40.0, 0.3};

    explicit EffectsSection(QWidget *parent = nullptr);

    //! The seven effect fields in wire order; the editor connects and aligns them.
    QList<ParameterField *> fields() const { return m_fields; }
    //! The vibration test's three fields (amplitude, frequency, duration).
    QList<ParameterField *> vibrationFields() const { return m_vibrationFields; }

    //! Whether the connected device renders effects; `reason` says why not ("the legacy
    //! protocol …"), shown above the fields. The fields stay editable (they are the profile's);
    //! the vibration test needs the device.
    void setAvailable(bool available, const QString &reason);
    bool isAvailable() const { return m_available; }

    //! The figures and warnings of `effects` on top of `device` (effects.md § 4), for a knob
    //! rendered at `controlRate` [Hz]; `valid` false shows none (figures of an invalid set mean
    //! nothing). The vibration test is checked against `tauLimit` and `controlRate` too.
    void setFigures(const EffectParams &effects, const DeviceParams &device, double tauLimit,
                    double controlRate, bool valid);
    //! Every warning shown, one per line (for tests and the status bar).
    QString warningText() const;

    Vibration vibration() const;
    void setVibration(const Vibration &vibration);
    //! The vibration test's rule violations ("frequency: must be < half the control rate …").
    QStringList vibrationProblems() const { return m_vibrationProblems; }

    QPushButton *vibrateButton() const { return m_vibrate; }
    QPushButton *stopButton() const { return m_stop; }

Q_SIGNALS:
    void vibrateRequested(const hatpic::Vibration &vibration); //!< Vibrate, or Stop (a = 0)

private:
    //! One warning in words, with the knob's damping `b` [N·m·s/rad] and period `h` [s].
    static QString sayWarning(EffectWarning warning, const EffectParams &effects,
                              const DeviceParams &device, const EffectFigures &f, double b,
                              double h);
    QWidget *buildVibrationGroup();
    void revalidateVibration();
    void refreshButtons();
    void rememberVibration() const;

    QList<ParameterField *> m_fields;
    QList<ParameterField *> m_vibrationFields;
    QLabel *m_unavailable = nullptr;
    QLabel *m_figures = nullptr;
    QLabel *m_warnings = nullptr;
    QPushButton *m_vibrate = nullptr;
    QPushButton *m_stop = nullptr;
    bool m_available = false;
    double m_tauLimit = HostParams{}.tau_limit;
    double m_controlRate = 0; //!< [Hz]; the editor's, given with the figures
    QStringList m_vibrationProblems;
    QStringList m_warningList;
};

} // namespace hatpic
