#include "connection/bridgepanel.h"
#include "connection/bridgepanelform.h"

#ifdef HATPIC_HAVE_BRIDGE
#include "bridge/bridge.h"
#include "connection/passivityview.h"
#include "connection/robotsideview.h"
#include "ros/node.h"
#endif

#include <QAbstractItemView>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QVBoxLayout>

#include <cmath>

namespace hatpic {

using namespace Qt::StringLiterals;
using bridge::BridgeSettings;
using bridge::Component;
using bridgeform::kNeeds;
using bridgeform::kTopicFields;
using bridgeform::spin;
using bridgeform::taken;

namespace {

//! Wrenches in a row whose chosen component was 0 while another was not, before the panel
//! says so (at 50 Hz, a fifth of a second).
constexpr std::uint64_t kOtherComponentStreak = 10;

} // namespace

bool BridgePanel::isBuilt()
{
#ifdef HATPIC_HAVE_BRIDGE
    return true;
#else
    return false;
#endif
}

BridgePanel::BridgePanel(DeviceClient &client, QWidget *parent) : QWidget(parent), m_client(client)
{
    // The panel scrolls its own content: its many fields never set the window's minimum size.
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto *content = new QWidget(scroll);
    auto *layout = new QVBoxLayout(content);
    m_grid = new QGridLayout;
    layout->addLayout(m_grid);
    layout->addStretch(1);
    scroll->setWidget(content);
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    // The loop's state at a glance, above what scrolls (issue 27: the passivity warning sat at
    // the bottom of the scroll area, out of sight).
    m_loop = new QLabel(this);
    m_loop->setObjectName(u"bridge_loop_state"_s);
    m_loop->setWordWrap(true);
    m_loop->setContentsMargins(6, 4, 6, 4);
    outer->addWidget(m_loop);
    outer->addWidget(scroll);
    showLoopState(tr("Bridge off"), LoopState::Off);

    auto *ros = new QGroupBox(tr("ROS"), content);
    ros->setObjectName(u"bridge_section_ros"_s);
    auto *rosLayout = new QVBoxLayout(ros);
    m_needs = new QLabel(ros);
    m_needs->setObjectName(u"bridge_needs"_s);
    m_needs->setWordWrap(true);
    QString needs = u"<b>"_s + tr("Needs") + u"</b><ul style=\"margin-left: -20px\">"_s;
    for (const char *line : kNeeds)
        needs += u"<li>"_s + tr(line).toHtmlEscaped() + u"</li>"_s;
    m_needs->setText(needs + u"</ul>"_s);
    m_needs->setToolTip(tr("docs/ros.md has the topics, and how to publish a test wrench "
                           "from a ROS 2 machine"));
    rosLayout->addWidget(m_needs);
    m_status = new QLabel(ros);
    m_status->setObjectName(u"bridge_status"_s);
    m_status->setWordWrap(true);
    m_sections.append(ros);
    if (!isBuilt()) {
        rosLayout->addWidget(m_status);
        setStatus(tr("The robot bridge is not built into this tuner (configure with "
                     "-DHATPIC_BUILD_BRIDGE=ON; it needs Cyclone DDS). See docs/ros.md."),
                  true);
        arrangeSections();
        return;
    }
#ifdef HATPIC_HAVE_BRIDGE
    if (const auto id = ros::domainFromEnvironment(bridge::kMaxDomainId, nullptr))
        m_settings.domainId = *id; // a bad ROS_DOMAIN_ID: 0, and the bridge says why at start
    m_bridge = new bridge::Bridge(m_client, this);
#endif
    buildForm();
    showSettings();
    m_refresh.setInterval(kRefreshMs);
    connect(&m_refresh, &QTimer::timeout, this, &BridgePanel::refresh);
    setStatus(tr("Off"), false);
    refresh();
    arrangeSections();
}

BridgePanel::~BridgePanel()
{
    setBridgeEnabled(false);
}

QString BridgePanel::needsText()
{
    QStringList lines;
    for (const char *line : kNeeds)
        lines.append(tr(line));
    return lines.join(u'\n');
}

void BridgePanel::buildForm()
{
    QWidget *ros = m_sections.first();
    auto *rosLayout = static_cast<QVBoxLayout *>(ros->layout());
    m_enable = new QCheckBox(tr("Publish on ROS and feed the wrench back"), ros);
    m_enable->setObjectName(u"bridge_enable"_s);
    rosLayout->addWidget(m_enable);
    rosLayout->addWidget(m_status);
    auto *top = new QFormLayout;
    m_top = top;
    m_ros = new QComboBox(ros);
    m_ros->setObjectName(u"bridge_ros"_s);
    m_ros->addItem(tr("ROS 2"), 2);
    m_ros->addItem(tr("ROS 1"), 1);
    m_ros->setToolTip(tr("ROS 2 over Cyclone DDS, or ROS 1 through roscpp; not saved in profiles"));
#ifdef HATPIC_HAVE_BRIDGE
    if (!ros::Node::isAvailable(ros::RosVersion::Ros1)) {
        // Not built in: shown, but not to be chosen.
        m_ros->setItemData(1, false, Qt::UserRole - 1);
        m_ros->setItemData(1, tr("ROS 1 is not built into this tuner (it needs libroscpp-dev)"),
                           Qt::ToolTipRole);
    }
#endif
    top->addRow(tr("ROS"), m_ros);
    m_master = new QLabel(ros);
    m_master->setObjectName(u"bridge_master"_s);
    m_master->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_master->setToolTip(tr("The ROS 1 master (ROS_MASTER_URI), read when the tuner started"));
    top->addRow(tr("Master"), m_master);
    m_domain = new QSpinBox(ros);
    m_domain->setObjectName(u"bridge_domain"_s);
    m_domain->setRange(0, bridge::kMaxDomainId);
    m_domain->setKeyboardTracking(false);
    m_domain->setToolTip(tr("DDS domain (ROS_DOMAIN_ID); not saved in profiles"));
    top->addRow(tr("Domain"), m_domain);
    m_namespace = new QLineEdit(ros);
    m_namespace->setObjectName(u"bridge_namespace"_s);
    m_namespace->setToolTip(tr("The node's namespace: the default topics go under it (a knob per "
                               "student on one network); empty: none"));
    top->addRow(tr("Namespace"), m_namespace);
    m_rate = spin(ros, u"bridge_rate"_s, 0.01, bridge::kMaxPublishRateHz, 2, u" Hz"_s);
    m_rate->setToolTip(tr("Messages per topic per second, at most"));
    top->addRow(tr("Rate"), m_rate);
    rosLayout->addLayout(top);
    m_engaged = new QPushButton(tr("Engaged"), ros);
    m_engaged->setObjectName(u"bridge_engaged"_s);
    m_engaged->setCheckable(true);
    m_engaged->setChecked(true);
    m_engaged->setToolTip(tr("The enable switch: released, the twist and τ_ext are zero and the "
                             "pose holds; engaged again, the pose goes on from there (with an "
                             "enable topic, both must be on)"));
    rosLayout->addWidget(m_engaged);
    // The operator's axis (ros.md § Choosing the knob's axis), as the axis topics choose it.
    auto *axisForm = new QFormLayout;
    m_axis = new QComboBox(ros);
    m_axis->setObjectName(u"bridge_axis"_s);
    for (int slot = 0; slot < 6; ++slot)
        m_axis->addItem(QString::fromStdString(Component::fromSlot(slot)->twistName()));
    m_axis->setToolTip(tr("The axis the knob drives while the bridge runs. A change waits until "
                          "the knob rests in its dead zone, the references go on without a "
                          "jump, and the knob then feels that axis's force or torque"));
    axisForm->addRow(tr("Knob drives"), m_axis);
    m_axisState = new QLabel(ros);
    m_axisState->setObjectName(u"bridge_axis_state"_s);
    m_axisState->setWordWrap(true);
    axisForm->addRow(m_axisState);
    rosLayout->addLayout(axisForm);
    rosLayout->addStretch(1);

    QWidget *content = ros->parentWidget();
    auto *feedback = new QGroupBox(tr("Wrench → τ_ext (live)"), content);
    feedback->setObjectName(u"bridge_section_feedback"_s);
    auto *feedbackForm = new QFormLayout(feedback);
    m_component = new QComboBox(feedback);
    m_component->setObjectName(u"bridge_component"_s);
    for (const bool angular : {false, true}) {
        for (int index = 0; index < 3; ++index)
            m_component->addItem(QString::fromStdString(Component{angular, index}.wrenchName()));
    }
    feedbackForm->addRow(tr("Component"), m_component);
    m_gain = spin(feedback, u"bridge_gain"_s, -bridge::kMaxFeedbackGain, bridge::kMaxFeedbackGain,
                  4, u" N·m/N"_s);
    m_gain->setSingleStep(0.01);
    feedbackForm->addRow(tr("Gain"), m_gain);
    m_limit = spin(feedback, u"bridge_limit"_s, 0, bridge::kMaxFeedbackLimit, 3, u" N·m"_s);
    m_limit->setSingleStep(0.01);
    feedbackForm->addRow(tr("Limit"), m_limit);
    m_stale = spin(feedback, u"bridge_stale"_s, 0.001, bridge::kMaxStaleAfter, 3, u" s"_s);
    m_stale->setToolTip(tr("A wrench older than this gives τ_ext 0"));
    feedbackForm->addRow(tr("Stale after"), m_stale);
    m_wrench = new QLabel(feedback);
    m_wrench->setObjectName(u"bridge_last_wrench"_s);
    feedbackForm->addRow(tr("Last wrench"), m_wrench);
    m_otherComponent = new QLabel(feedback);
    m_otherComponent->setObjectName(u"bridge_other_component"_s);
    m_otherComponent->setWordWrap(true);
    m_otherComponent->setStyleSheet(u"color: #b00020;"_s);
    feedbackForm->addRow(m_otherComponent);
    m_tauExt = new QLabel(feedback);
    m_tauExt->setObjectName(u"bridge_tau_ext"_s);
    feedbackForm->addRow(tr("τ_ext"), m_tauExt);
    m_counts = new QLabel(feedback);
    m_counts->setObjectName(u"bridge_counts"_s);
    m_counts->setWordWrap(true);
    feedbackForm->addRow(tr("Wrenches"), m_counts);
    m_sections.append(feedback);

    auto *topics = new QGroupBox(tr("Topics (empty: not used)"), content);
    topics->setObjectName(u"bridge_section_topics"_s);
    auto *topicForm = new QFormLayout(topics);
    for (std::size_t i = 0; i < std::size(kTopicFields); ++i) {
        m_topics.append(new QLineEdit(topics));
        m_topics[i]->setObjectName(QString::fromUtf16(kTopicFields[i].name));
        topicForm->addRow(tr(kTopicFields[i].label), m_topics[i]);
        connect(m_topics[i], &QLineEdit::editingFinished, this, [this] { edited(true); });
    }
    m_published = new QLabel(topics);
    m_published->setObjectName(u"bridge_published"_s);
    m_published->setWordWrap(true);
    topicForm->addRow(m_published);
    m_sections.append(topics);
#ifdef HATPIC_HAVE_BRIDGE
    // What the running loop does comes right after ROS, before the settings: the robot side
    // and the passivity in reach without scrolling past the topics (issue 27).
    m_robotSide = new RobotSideView(content);
    m_passivityView = new PassivityView(content);
    m_sections.insert(1, m_passivityView);
    m_sections.insert(2, m_robotSide);
#endif

    connect(m_enable, &QCheckBox::toggled, this, &BridgePanel::setBridgeEnabled);
    connect(m_ros, &QComboBox::currentIndexChanged, this, [this] {
        showNetworkRows();
        edited(true);
    });
    connect(m_domain, &QSpinBox::valueChanged, this, [this] { edited(true); });
    connect(m_rate, &QDoubleSpinBox::valueChanged, this, [this] { edited(false); });
    for (QDoubleSpinBox *box : {m_gain, m_limit, m_stale})
        connect(box, &QDoubleSpinBox::valueChanged, this, [this] { edited(false); });
    connect(m_component, &QComboBox::currentIndexChanged, this, [this] { edited(false); });
    connect(m_axis, &QComboBox::activated, this, [this]([[maybe_unused]] int slot) {
#ifdef HATPIC_HAVE_BRIDGE
        if (m_bridge)
            m_bridge->selectAxis(*Component::fromSlot(slot));
#endif
        refresh();
    });
    connect(m_namespace, &QLineEdit::editingFinished, this, [this] { edited(true); });
    connect(m_engaged, &QPushButton::toggled, this, [this](bool engaged) {
        m_engaged->setText(engaged ? tr("Engaged") : tr("Released"));
#ifdef HATPIC_HAVE_BRIDGE
        m_bridge->setEngaged(engaged);
#endif
    });
}

void BridgePanel::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    arrangeSections();
}

void BridgePanel::arrangeSections()
{
    // The panel's own width (the scroll area's), not its content's: the content is as wide as
    // its columns need, and would never let fewer columns be chosen.
    const int spacing = m_grid->horizontalSpacing() > 0 ? m_grid->horizontalSpacing() : 6;
    const int room = width() - 2 * spacing - style()->pixelMetric(QStyle::PM_ScrollBarExtent);
    int columns = static_cast<int>(m_sections.size());
    for (; columns > 1; --columns) {
        int needed = 0;
        for (int i = 0; i < columns; ++i)
            needed += m_sections[i]->sizeHint().width() + spacing;
        if (needed <= room)
            break;
    }
    if (columns == m_columns)
        return;
    m_columns = columns;
    for (QWidget *section : std::as_const(m_sections))
        m_grid->removeWidget(section);
    for (int i = 0; i < m_sections.size(); ++i)
        m_grid->addWidget(m_sections[i], i / columns, i % columns, Qt::AlignTop);
    for (int c = 0; c < m_sections.size(); ++c)
        m_grid->setColumnStretch(c, c < columns ? 1 : 0);
}

void BridgePanel::showSettings()
{
    if (!m_bridge)
        return;
    const QSignalBlocker b1(m_domain), b2(m_rate), b3(m_component), b4(m_gain), b5(m_limit),
        b6(m_stale), b7(m_ros);
    m_ros->setCurrentIndex(m_ros->findData(m_settings.rosVersion));
    showNetworkRows();
    m_domain->setValue(m_settings.domainId);
    m_rate->setValue(m_settings.publishRateHz);
    const Component c = m_settings.feedback.component;
    m_component->setCurrentIndex(c.slot());
    m_gain->setValue(m_settings.feedback.gain);
    m_limit->setValue(m_settings.feedback.limit);
    m_stale->setValue(m_settings.feedback.staleAfter);
    for (std::size_t i = 0; i < std::size(kTopicFields); ++i)
        m_topics[i]->setText(QString::fromStdString(m_settings.topics.*kTopicFields[i].topic));
    m_namespace->setText(QString::fromStdString(m_settings.nodeNamespace));
}

void BridgePanel::setSettings(const BridgeSettings &settings)
{
    if (!m_bridge)
        return;
    m_settings = bridge::withNetworkOf(settings, m_settings);
    showSettings();
    if (isRunning())
        setBridgeEnabled(true); // reopens with the new settings
}

void BridgePanel::edited(bool reopen)
{
    BridgeSettings s = m_settings;
    s.rosVersion = m_ros->currentData().toInt();
    s.domainId = m_domain->value();
    s.publishRateHz = taken(m_rate, m_settings.publishRateHz);
    const int c = m_component->currentIndex();
    s.feedback.component = *Component::fromSlot(c);
    s.feedback.gain = taken(m_gain, m_settings.feedback.gain);
    s.feedback.limit = taken(m_limit, m_settings.feedback.limit);
    s.feedback.staleAfter = taken(m_stale, m_settings.feedback.staleAfter);
    for (std::size_t i = 0; i < std::size(kTopicFields); ++i)
        s.topics.*kTopicFields[i].topic = m_topics[i]->text().trimmed().toStdString();
    s.nodeNamespace = m_namespace->text().trimmed().toStdString();
    if (s == m_settings)
        return;
    if (const auto errors = bridge::validate(s); !errors.empty()) {
        setStatus(tr("Not applied: %1.").arg(QString::fromStdString(errors.front())), true);
        return;
    }
    const bool feedbackChanged = s.feedback != m_settings.feedback;
    const bool rateChanged = s.publishRateHz != m_settings.publishRateHz;
    m_settings = s;
#ifdef HATPIC_HAVE_BRIDGE
    if (isRunning()) {
        if (reopen) {
            setBridgeEnabled(true);
        } else {
            if (feedbackChanged) {
                // A limit above the connected device's tau_limit is the bridge's refusal.
                if (const QString problem = m_bridge->setFeedbackSettings(s.feedback);
                    !problem.isEmpty()) {
                    m_settings.feedback = m_bridge->settings().feedback;
                    setStatus(tr("Not applied: %1").arg(problem), true);
                    return;
                }
            }
            if (rateChanged)
                m_bridge->setPublishRate(s.publishRateHz);
            setStatus(runningText(), false);
        }
    } else {
        setStatus(tr("Off"), false);
    }
#else
    Q_UNUSED(reopen);
    Q_UNUSED(feedbackChanged);
    Q_UNUSED(rateChanged);
#endif
    Q_EMIT settingsEdited(m_settings);
}

void BridgePanel::setReferenceMode(ReferenceMode mode)
{
    m_mode = mode;
#ifdef HATPIC_HAVE_BRIDGE
    if (m_bridge)
        m_bridge->setReferenceMode(mode);
#endif
}

bool BridgePanel::isRunning() const
{
#ifdef HATPIC_HAVE_BRIDGE
    return m_bridge && m_bridge->isRunning();
#else
    return false;
#endif
}

bool BridgePanel::startOn(int rosVersion)
{
    const int index = m_ros ? m_ros->findData(rosVersion) : -1;
    if (!m_bridge || index < 0 || m_ros->itemData(index, Qt::UserRole - 1) == QVariant(false)) {
        setStatus(tr("Cannot start: ROS %1 is not built into this tuner.").arg(rosVersion), true);
        return false; // not built in: absent, or an item shown disabled
    }
    m_settings.rosVersion = rosVersion;
    showSettings();
    setBridgeEnabled(true);
    return isRunning();
}

void BridgePanel::setBridgeEnabled(bool on)
{
#ifdef HATPIC_HAVE_BRIDGE
    if (!m_bridge)
        return;
    QString error;
    if (on) {
        error = m_bridge->start(m_settings); // stops first: a running bridge reopens
        m_passivityView->clear();            // E starts again at 0
    } else
        m_bridge->stop();
    const bool running = m_bridge->isRunning();
    {
        const QSignalBlocker blocker(m_enable);
        m_enable->setChecked(running);
    }
    // What the bridge needs is for starting it: once it runs, the loop's sections take its room.
    m_needs->setVisible(!running);
    if (running) {
        m_refresh.start();
        setStatus(runningText(), false);
    } else {
        m_refresh.stop();
        setStatus(error.isEmpty() ? tr("Off") : tr("Cannot start: %1").arg(error),
                  !error.isEmpty());
    }
    refresh();
#else
    Q_UNUSED(on);
#endif
}

void BridgePanel::refresh()
{
#ifdef HATPIC_HAVE_BRIDGE
    if (!m_bridge)
        return;
    const bridge::BridgeStats s = m_bridge->stats();
    const bool running = m_bridge->isRunning();
    // Once the operator chose an axis the knob feels that axis's component (Bridge::selectAxis).
    const Component c = running ? s.feltComponent : m_settings.feedback.component;
    showAxis(s, running);
    // The whole wrench, so that a robot sending on another component shows.
    m_wrench->setText(bridgeform::wrenchText(s.lastWrenchValues));
    m_wrench->setToolTip(
        tr("x y z; the component fed back: %1").arg(QString::fromStdString(c.wrenchName())));
    const QString other = s.otherComponentStreak >= kOtherComponentStreak
                              ? bridgeform::otherComponentWarning(s.lastWrenchValues, c)
                              : QString();
    m_otherComponent->setText(other);
    m_otherComponent->setVisible(!other.isEmpty());
    // A board's knobs 2–4 feel their own axes' components (ros.md § A board's knobs).
    const int knobs = m_client.state() == SessionState::Connected ? m_client.deviceInfo().axes : 1;
    m_tauExt->setText(bridgeform::torquesText(s.torques, knobs));
    m_counts->setText(tr("%1 received, %2 non-finite, %3 stale, %4 limited")
                          .arg(s.wrenches.received)
                          .arg(s.wrenches.nonFinite)
                          .arg(s.wrenches.stale)
                          .arg(s.wrenches.limited));
    QString out = tr("Published:");
    for (int i = 0; i < bridge::kOutTopicCount; ++i)
        out += u' ' + QString::fromLatin1(bridge::outTopicKey(bridge::OutTopic(i))) + u' ' +
               QString::number(s.published[i]) + (i + 1 < bridge::kOutTopicCount ? u","_s : u""_s);
    m_published->setText(out);
    m_robotSide->setStats(s, c);
    m_passivityView->setState(s.passivity);
    if (!running)
        showLoopState(tr("Bridge off"), LoopState::Off);
    else if (s.passivity.warning)
        showLoopState(tr("Loop generating energy: see Passivity below"), LoopState::Generating);
    else if (s.passivity.dampedAtRest)
        showLoopState(tr("Loop held at rest by damping: see Passivity below"), LoopState::Passive);
    else if (s.passivity.inContact)
        showLoopState(tr("Loop passive, in contact"), LoopState::Passive);
    else
        showLoopState(tr("Loop passive, no contact"), LoopState::Passive);
#endif
}

#ifdef HATPIC_HAVE_BRIDGE
void BridgePanel::showAxis(const bridge::BridgeStats &s, bool running)
{
    m_axis->setEnabled(running);
    if (!m_axis->view()->isVisible()) { // not while the user picks one
        const QSignalBlocker blocker(m_axis);
        m_axis->setCurrentIndex(running ? s.pendingAxis.value_or(s.axis).slot()
                                        : m_settings.axisFor(m_mode).slot());
    }
    QString text;
    if (running && s.pendingAxis == s.axis) // the driven axis, chosen: its component to come
        text = tr("Drives %1; feels %2 once the knob rests in its dead zone")
                   .arg(QString::fromStdString(s.axis.twistName()),
                        QString::fromStdString(s.axis.wrenchName()));
    else if (running && s.pendingAxis)
        text = tr("Drives %1; %2 once the knob rests in its dead zone")
                   .arg(QString::fromStdString(s.axis.twistName()),
                        QString::fromStdString(s.pendingAxis->twistName()));
    else if (running)
        text = tr("Feels %1").arg(QString::fromStdString(s.feltComponent.wrenchName()));
    if (running && s.axisRejected > 0)
        text += tr("; %1 refused on the axis topics, the last '%2' (not linear.x … angular.z, "
                   "or 0 … 5)")
                    .arg(s.axisRejected)
                    .arg(QString::fromStdString(s.lastAxisRejected));
    m_axisState->setText(text);
    m_axisState->setVisible(!text.isEmpty());
}
#endif

void BridgePanel::showLoopState(const QString &text, LoopState state)
{
    if (text == m_loopText && state == m_loopState)
        return;
    m_loopText = text;
    m_loopState = state;
    m_loop->setText(u"<b>"_s + text.toHtmlEscaped() + u"</b>"_s);
    // Only while there is a loop: off, the ROS section's status says so, and the room goes
    // to what the bridge needs and its switch (in sight at 1280×720).
    m_loop->setVisible(state != LoopState::Off);
    // Good in green, bad in the warnings' red, off in the window's own colours.
    m_loop->setStyleSheet(state == LoopState::Generating ? u"color: white; background: #b00020;"_s
                          : state == LoopState::Passive  ? u"color: #1b7f3b;"_s
                                                         : QString());
    Q_EMIT loopStateChanged(text, state);
}

QString BridgePanel::runningText() const
{
#ifdef HATPIC_HAVE_BRIDGE
    if (m_settings.rosVersion == 1)
        return tr("Running on %1").arg(m_bridge->where());
#endif
    return tr("Running on domain %1").arg(m_settings.domainId);
}

void BridgePanel::showNetworkRows()
{
    const bool ros1 = m_ros->currentData().toInt() == 1;
    m_top->setRowVisible(m_domain, !ros1);
    m_top->setRowVisible(m_master, ros1);
    const QByteArray master = qgetenv("ROS_MASTER_URI");
    m_master->setText(master.isEmpty() ? tr("roscpp's default (ROS_MASTER_URI is not set)")
                                       : QString::fromLocal8Bit(master));
}

void BridgePanel::setStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(error ? u"color: #b00020;"_s : QString());
}

} // namespace hatpic
