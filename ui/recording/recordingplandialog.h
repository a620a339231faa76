// How the next recording starts and how long it runs (RecordingPlan): now, on the next push,
// or when θ or τ crosses a level (rising or falling); a span kept from before the trigger; a
// fixed length or until stopped. Values are SI (θ in rad, τ in N·m, times in s).
#pragma once

#include "telemetry/recordingtrigger.h"

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;
class QSettings;

namespace hatpic {

class RecordingPlanDialog : public QDialog
{
    Q_OBJECT
public:
    explicit RecordingPlanDialog(QWidget *parent = nullptr);

    void setPlan(const RecordingPlan &plan);
    RecordingPlan plan() const;

    //! What a person reads about `plan`: "θ rising through 0.2 rad", "the next push".
    static QString describeTrigger(const RecordingPlan &plan);
    //! The plan as saved under "recording/plan/…"; defaults for what is missing.
    static RecordingPlan loadPlan(const QSettings &settings);
    static void savePlan(QSettings &settings, const RecordingPlan &plan);

private:
    void updateEnabled();

    QComboBox *m_start = nullptr;
    QComboBox *m_quantity = nullptr;
    QComboBox *m_edge = nullptr;
    QDoubleSpinBox *m_level = nullptr;
    QDoubleSpinBox *m_pre = nullptr;
    QDoubleSpinBox *m_duration = nullptr;
};

} // namespace hatpic
