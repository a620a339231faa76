// One numeric parameter row of the editor: name and meaning, spin box, unit, slider, the rule
// it breaks, and a marker when it differs from the device.
#pragma once

#include <QList>
#include <QObject>
#include <QString>

#include <optional>

class QGridLayout;
class QLabel;
class QSlider;
class QWidget;

namespace hatpic {

class ScientificSpinBox;

class ParameterField : public QObject
{
    Q_OBJECT
public:
    struct Spec
    {
        QString key;        //!< model name, e.g. "K_min"; also the widgets' object names
        QString symbol;     //!< what the label shows, e.g. "K_min" or "θ0"
        QString meaning;    //!< "minimum re-centering stiffness"
        QString unit;       //!< SI unit text, e.g. "N·m/rad"
        QString toolTip;    //!< longer explanation
        double minimum = 0; //!< spin box range, SI (per-field rules; cross-field rules aside)
        double maximum = 1;
        bool minimumExclusive = false; //!< the rule is "> minimum": typing below it is refused
        bool maximumExclusive = false; //!< the rule is "< maximum": typing above it is refused
        double sliderMin = 0;          //!< practical slider range, SI
        double sliderMax = 1;
        bool logSlider = false;    //!< slider moves in decades (for D_adm, M_adm)
        bool relativeStep = false; //!< spin arrows step the 2nd significant digit
        double step = 0.01;        //!< fixed spin step, SI
        bool angle = false;        //!< shown in degrees when the editor says so
    };

    static constexpr int kSliderTicks = 1000;

    //! Creates its widgets as children of `parentWidget`; call addToGrid to place them.
    ParameterField(const Spec &spec, QWidget *parentWidget, QObject *parent = nullptr);

    //! Gives all name labels (plus `extraNames`) one width, and all unit labels another, so
    //! rows in different grids line up.
    static void alignColumns(const QList<ParameterField *> &fields,
                             const QList<QLabel *> &extraNames = {});

    //! Places the row at `row` and its message line at `row + 1`.
    void addToGrid(QGridLayout *grid, int row);
    //! A grid for fields, spaced as every group of the editor is (on `parent`, or none).
    static QGridLayout *newGrid(QWidget *parent);

    const Spec &spec() const { return m_spec; }
    double value() const { return m_value; } //!< SI
    //! Shows a value without emitting edited().
    void setValue(double value);

    void setAngleInDegrees(bool degrees);
    void setUnit(const QString &unit); //!< e.g. v_max: "m/s" or "rad/s"

    //! The rule this field breaks (from validate()), or empty when fine.
    void setProblem(const QString &problem);
    QString problem() const { return m_problem; }
    //! What became of the last entry the field could not take as typed, in words (clamped to
    //! a bound, refused beyond an exclusive one, not a number); empty when none. It goes with
    //! the next edit, and with a value set from outside (undo, Revert, a profile).
    QString clampNote() const { return m_note; }
    //! A maximum known only at run time (the vibration test's f < half the control rate):
    //! `exclusive` when the rule is "< maximum".
    void setMaximum(double maximum, bool exclusive);

    //! The device's value for the diff marker; nullopt hides the marker.
    void setDeviceValue(std::optional<double> deviceValue);
    //! True when a device value is known and differs after rounding to float32 (the wire type).
    bool differsFromDevice() const;

    ScientificSpinBox *spinBox() const { return m_spin; }
    QLabel *unitLabel() const { return m_unit; }
    QSlider *slider() const { return m_slider; }

Q_SIGNALS:
    void edited(double value); //!< the user changed the value [SI]
    void editFinished();       //!< end of typing or dragging: the next edit is a new undo step

private:
    double displayScale() const;
    double sliderToValue(int position) const;
    int valueToSlider(double value) const;
    void updateSpinRange();
    void updateSlider();
    void updateMarker();
    void updateMessage();
    void showClamp(double typed, double bound);
    void showRefusal(double typed, double bound);
    void showNotANumber(const QString &typed);
    QString unitSuffix() const; //!< " N·m/rad", or "°" for an angle shown in degrees
    QString numberText(double value) const;

    Spec m_spec;
    double m_value = 0;
    bool m_degrees = false;
    QString m_problem;
    QString m_note;
    std::optional<double> m_device;

    QLabel *m_marker = nullptr;
    QLabel *m_label = nullptr;
    ScientificSpinBox *m_spin = nullptr;
    QLabel *m_unit = nullptr;
    QSlider *m_slider = nullptr;
    QLabel *m_message = nullptr;
};

} // namespace hatpic
