#include "editor/chatterdetector.h"

#include "editor/derivedfiguresview.h"
#include "editor/parametereditor.h"

#include <cmath>

namespace hatpic {

void ChatterDetector::setParams(const std::optional<DeviceParams> &params)
{
    m_theta0 = params ? params->theta0 : 0.0;
    m_qdz = params ? params->Q_dz : 0.0;
    restart();
}

bool ChatterDetector::watchesEdgeOf(const std::optional<DeviceParams> &params) const
{
    return m_theta0 == (params ? params->theta0 : 0.0) && m_qdz == (params ? params->Q_dz : 0.0);
}

void ChatterDetector::restart()
{
    m_outside.reset();
    m_crossings.clear();
}

void ChatterDetector::add(const Sample &sample)
{
    if (!(m_qdz > 0) || !std::isfinite(sample.theta) || !std::isfinite(sample.t_s))
        return;
    // Time going back is another session: start again.
    if (m_outside && sample.t_s < m_last)
        restart();
    const bool outside = std::abs(sample.theta - m_theta0) >= m_qdz;
    if (m_outside && *m_outside != outside)
        m_crossings.push_back(sample.t_s);
    m_outside = outside;
    m_last = sample.t_s;
    while (!m_crossings.empty() && m_crossings.front() < sample.t_s - kWindow)
        m_crossings.pop_front();
}

std::optional<double> ChatterDetector::frequency() const
{
    const auto n = m_crossings.size();
    if (n < std::size_t(kMinCrossings))
        return std::nullopt;
    const double span = m_crossings.back() - m_crossings.front();
    if (!(span > 0))
        return std::nullopt;
    return double(n - 1) / 2.0 / span;
}

ChatterWatch::ChatterWatch(ParameterEditor *editor) : QObject(editor), m_editor(editor)
{
    // The knob tuned, against its own tuning: the model's device tuning is that knob's. A
    // change that moves no edge (K_max, a read-back of the same) keeps what was counted.
    connect(editor->model(), &TuningModel::deviceChanged, this, [this] {
        if (const auto &params = m_editor->deviceTuning().params; !m_detector.watchesEdgeOf(params))
            m_detector.setParams(params);
    });
    connect(editor, &ParameterEditor::knobSelected, this,
            [this] { m_detector.setParams(m_editor->deviceTuning().params); }); // another θ
    m_detector.setParams(m_editor->deviceTuning().params);
}

void ChatterWatch::addSamples(const SampleBatch &batch)
{
    // Knob 1 is the sample, knob k its board's block.
    const int knob = m_editor->knob();
    for (const Sample &s : batch) {
        if (knob == 0) {
            m_detector.add(s);
        } else if (s.board && knob < s.board->axes) {
            Sample other;
            other.t_s = s.t_s;
            other.theta = s.board->more[std::size_t(knob - 1)].theta;
            m_detector.add(other);
        }
    }
    const std::optional<DeviceParams> &params = m_editor->deviceTuning().params;
    m_editor->derivedFiguresView()->setChatter(m_detector.frequency(),
                                               params ? params->K_max * params->Q_dz : 0.0);
}

} // namespace hatpic
