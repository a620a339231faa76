// The stability map of the teleoperation loop (docs/teleop.md § The stability map): the loop of
// loopsimulation.h run for every one-way delay × feedback gain × value of one tuning field,
// each cell on its own, spread over threads. Its table as CSV and its chart as SVG, one
// definition each for `hatpicctl teleop-map` and the tuner's Experiments panel.
#pragma once

#include "teleop/loopsimulation.h"

#include <QByteArray>
#include <QString>

#include <atomic>
#include <functional>
#include <optional>
#include <vector>

namespace hatpic::teleop {

//! A list of values as the options give it: comma-separated items, each a number, FROM:TO:STEP
//! (FROM, FROM+STEP, … up to TO inclusive) or FROM:TO/N (N values evenly from FROM to TO).
//! On failure nullopt and `error` names the rule and the text.
std::optional<std::vector<double>> parseValueList(const QString &text, QString *error);
constexpr int kMaxListValues = 1000; //!< values in one list at most

//! A tuning field the map varies (besides delay and gain): a device parameter, a host
//! setting or a passivity parameter, by the name the profile gives it.
struct MapField
{
    QString name;               //!< "pc_damping_max", "M_adm", …
    std::vector<double> values; //!< one map per value
};

//! The tuning fields a map can vary, in the tables' order.
QStringList mapFieldNames();
//! The field's value in `config`; nullopt when no such field.
std::optional<double> fieldValue(const LoopConfig &config, const QString &name);
//! Sets the field in `config`; false when no such field.
bool setFieldValue(LoopConfig &config, const QString &name, double value);

struct MapSpec
{
    LoopConfig base; //!< everything but the delay, the gain, the hand and the field
    std::vector<double> delays{0.0};
    std::vector<double> gains{0.02};
    //! Constant hands' torques [N·m], a map each; empty: the base's hand only.
    std::vector<double> hands;
    MapField field; //!< name empty: the base's tuning only
    int threads = 2;

    //! The cells' count: delays × gains × hands × field values (at least one).
    qsizetype cellCount() const;
    //! The config of cell `index` (field value slowest, then hand, then gain, delay fastest).
    LoopConfig cellConfig(qsizetype index) const;
};

constexpr qsizetype kMaxMapCells = 100000;
constexpr int kMaxMapThreads = 64;

//! Empty when `spec` can run, else one sentence (a bad cell's config names its field).
QString checkSpec(const MapSpec &spec);

struct MapCell
{
    double delay = 0;  //!< one-way [s]
    double gain = 0;   //!< [N·m/N]
    double hand = 0;   //!< the hand's torque [N·m] (NaN: a hand that is not constant)
    double field = 0;  //!< the varied field's value (NaN: no field varied)
    double pc = 0;     //!< pc_damping_max used [N·m·s/rad] (0: no controller)
    LoopResult result; //!< the worst contact's figures
    std::vector<LoopResult> contacts; //!< each contact's, in order
};

//! Runs every cell of a checked `spec` on `spec.threads` threads; `progress(done, total)`
//! runs on those threads. A set `cancel` stops early: the cells not run are missing.
std::vector<MapCell> runMap(const MapSpec &spec,
                            const std::function<void(qsizetype, qsizetype)> &progress = {},
                            const std::atomic<bool> *cancel = nullptr);

//! The CSV (docs/teleop.md): header, then one row per cell and contact.
QByteArray mapCsv(const std::vector<MapCell> &cells, const QString &fieldName);

//! Where a chart marks the settings in use.
struct MapMark
{
    double delay = 0;
    double gain = 0;
    double field = 0;               //!< the panel it is on (NaN: the only one)
    double hand = LoopResult::kNaN; //!< the hand's panel it is on (NaN: every one)
};

//! The chart: one panel per field value and hand, delay across, gain up; a settled cell
//! coloured by its worst contact's settle time (scale 0 … duration), an unsettled one grey and
//! crossed.
QByteArray mapSvg(const std::vector<MapCell> &cells, const QString &fieldName, double duration,
                  const std::optional<MapMark> &mark = std::nullopt);

} // namespace hatpic::teleop
