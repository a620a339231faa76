// The editor's fields in their groups: the device's parameters (admittance filter,
// re-centering stiffness), its effects, its passivity controller, and the host's reference
// model (mode, v_max,
// tau_limit, dead-zone hold), with one column width for names and units so the spin boxes line
// up. It shows a tuning, the device's values beside it and each field's problems, and reports
// what the user changes; the editor decides what an edit does.
#pragma once

#include "model/devicetuning.h"
#include "tuning/tuning.h"

#include <QHash>
#include <QStringList>
#include <QWidget>

#include <optional>
#include <string_view>

class QCheckBox;
class QComboBox;
class QLabel;

namespace hatpic {

class EffectsSection;
class ParameterField;

class ParameterForm : public QWidget
{
    Q_OBJECT
public:
    explicit ParameterForm(QWidget *parent = nullptr);

    //! The row of a numeric field by model name ("K_max", "v_max", "wall_max", …), or nullptr.
    ParameterField *field(const QString &key) const { return m_fields.value(key); }
    EffectsSection *effectsSection() const { return m_effectsSection; }

    //! Shows `tuning` in the fields, the mode and the dead-zone hold; no edit is reported.
    void showTuning(const Tuning &tuning);
    //! The device's values beside the fields (none without them). An effect field shows its
    //! own value when what it sends (`effectsOnWire`) is the device's; a passivity field when
    //! its float32 is the device's.
    void showDevice(const DeviceTuning &device, const Tuning &edited,
                    const EffectParams &effectsOnWire);
    //! Whether the connected device has the passivity controller; `reason` says why not, shown
    //! above the fields (which stay editable: they are the profile's).
    void setPassivityAvailable(bool available, const QString &reason);
    //! Each field's problems, one a line; a field not in `perField` has none.
    void setProblems(const QHash<QString, QStringList> &perField);
    //! Display only: θ0, N and Q_dz in degrees.
    void setAngleInDegrees(bool degrees);

Q_SIGNALS:
    void fieldEdited(const QString &key, double value); //!< the user changed a field [SI]
    void editFinished(); //!< end of typing or dragging: the next edit is a new undo step
    void modeEdited(hatpic::ReferenceMode mode);
    void refDeadzoneEdited(bool on);

private:
    QWidget *buildDeviceGroups();
    QWidget *buildHostGroup();
    QWidget *buildEffectsGroup();
    QWidget *buildPassivityGroup();
    void addField(ParameterField *field);
    //! The device's values of one block beside its fields (effects, passivity): a field whose
    //! `onWire` value is the device's shows its own (`edited`).
    template<typename Block>
    void showBlockDevice(const std::optional<Block> &device, const Block &edited,
                         const Block &onWire, std::string_view (*name)(int));

    QHash<QString, ParameterField *> m_fields;
    QComboBox *m_mode = nullptr;
    QCheckBox *m_refDeadzone = nullptr;
    EffectsSection *m_effectsSection = nullptr;
    QLabel *m_passivityUnavailable = nullptr;
};

} // namespace hatpic
