// The Bridge panel (ros.md § In the tuner): the robot bridge inside the tuner, on the window's
// DeviceClient. Enable/disable; ROS 2 (with its domain) or ROS 1 (with its master), topics and
// rate (a change of ROS, domain or topic reopens the endpoints while running); gain, limit,
// component and staleness applied at once, so the feel can be tuned while the robot runs; the
// last wrench (all six components, with a warning when the chosen one stays 0 while another
// does not), the τ_ext it produced and the rejected counts; the node's namespace and the
// enable switch (Engaged / Released: the dead man's local half). It starts from
// bridge::panelDefaults() (force.x, the project's own robot). Without HATPIC_BUILD_BRIDGE the
// panel only says that the bridge is not built.
//
// It first says what the bridge needs (a line each in kNeeds, bridgepanelform.h: add one when a
// new way to get a wrench exists). Its sections — ROS (needs, enable, status, ROS version,
// domain or master, rate), the wrench's feedback, the topics — stand side by side as far as the
// panel's width allows, else under each other, and scroll: a new section is one more entry in
// m_sections.
// Two show the robot side as measured (RobotSideView) and the energy at the knob's port
// (PassivityView); they come right after ROS, and a header above the scroll area says the
// loop's state at a glance. It scrolls on its own, so it never sets the dock's size.
#pragma once

#include "model/params.h"
#include "profile/bridgesettings.h"

#include <QTimer>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QGridLayout;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace hatpic {

class DeviceClient;
class PassivityView;
class RobotSideView;

namespace bridge {
class Bridge;
struct BridgeStats;
} // namespace bridge

class BridgePanel : public QWidget
{
    Q_OBJECT
public:
    //! The robot loop at a glance: the panel's header and the window's status bar.
    enum class LoopState { Off, Passive, Generating };
    Q_ENUM(LoopState)

    static constexpr int kRefreshMs = 200; //!< readouts while running
    //! Whether this build has the bridge (HATPIC_BUILD_BRIDGE).
    static bool isBuilt();

    explicit BridgePanel(DeviceClient &client, QWidget *parent = nullptr);
    ~BridgePanel() override; //!< stops the bridge: τ_ext 0 to the device

    //! The settings shown (the domain from ROS_DOMAIN_ID, else 0, and ROS 2 until edited).
    const bridge::BridgeSettings &settings() const { return m_settings; }
    bool isRunning() const;
    //! What the bridge needs, as the panel says it (plain text).
    static QString needsText();
    //! Sections side by side now (1 … the number of sections).
    int columns() const { return m_columns; }
    //! The loop's state, as its header says it ("Loop passive, no contact", …).
    LoopState loopState() const { return m_loopState; }
    QString loopText() const { return m_loopText; }

public Q_SLOTS:
    //! New settings (a profile was opened); the ROS version and domain stay. While running they
    //! take effect at once.
    void setSettings(const hatpic::bridge::BridgeSettings &settings);
    //! Picks the default axis of the references (linear.x, or angular.z in rotation).
    void setReferenceMode(hatpic::ReferenceMode mode);
    //! Starts or stops the bridge, as the Enable box does.
    void setBridgeEnabled(bool on);
    //! Picks ROS `rosVersion` (1 or 2) and starts the bridge with the settings shown, as a user
    //! choosing it and ticking Enable (hatpic-tuner --bridge). False, with the panel saying
    //! why, when that ROS is not built in or the bridge cannot start.
    bool startOn(int rosVersion);

Q_SIGNALS:
    //! The user changed a setting (valid as a whole): for the profile.
    void settingsEdited(const hatpic::bridge::BridgeSettings &settings);
    //! The loop's state changed (the header's text and its state).
    void loopStateChanged(const QString &text, hatpic::BridgePanel::LoopState state);

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void buildForm();
    //! As many sections side by side as the width holds at their preferred widths.
    void arrangeSections();
    void showSettings();
    //! Takes an edit: checks the whole, applies it (live, or by reopening), tells the profile.
    void edited(bool reopen);
    void refresh();
    void setStatus(const QString &text, bool error);
    QString runningText() const;
    //! The Domain row for ROS 2, the Master row for ROS 1.
    void showNetworkRows();
    void showLoopState(const QString &text, LoopState state);
    //! The axis the knob drives, one it waits to drive, and refused selections.
    void showAxis(const bridge::BridgeStats &s, bool running);

    DeviceClient &m_client;
    bridge::Bridge *m_bridge = nullptr; //!< a child; null when not built
    bridge::BridgeSettings m_settings = bridge::panelDefaults();
    ReferenceMode m_mode = ReferenceMode::Translation; //!< the axis's default follows it
    QTimer m_refresh;

    QGridLayout *m_grid = nullptr; //!< the sections, in m_columns columns
    QList<QWidget *> m_sections;
    int m_columns = 0;
    QLabel *m_loop = nullptr; //!< the loop's state, above the scroll area
    QString m_loopText;
    LoopState m_loopState = LoopState::Off;
    QLabel *m_needs = nullptr;
    QLabel *m_status = nullptr;
    QCheckBox *m_enable = nullptr;
    QFormLayout *m_top = nullptr;
    QComboBox *m_ros = nullptr; //!< ROS 2, ROS 1 (data: the version)
    QLabel *m_master = nullptr; //!< ROS 1: ROS_MASTER_URI
    QSpinBox *m_domain = nullptr;
    QList<QLineEdit *> m_topics; //!< one per bridgeform::kTopicFields, in its order
    QLineEdit *m_namespace = nullptr;
    QPushButton *m_engaged = nullptr; //!< the local enable switch (dead man)
    QDoubleSpinBox *m_rate = nullptr;
    QComboBox *m_axis = nullptr;   //!< the axis the knob drives (Bridge::selectAxis())
    QLabel *m_axisState = nullptr; //!< … what it waits for, what the topics had refused
    QComboBox *m_component = nullptr;
    QDoubleSpinBox *m_gain = nullptr;
    QDoubleSpinBox *m_limit = nullptr;
    QDoubleSpinBox *m_stale = nullptr;
    QLabel *m_wrench = nullptr;
    QLabel *m_otherComponent = nullptr; //!< the chosen component stays 0, another does not
    QLabel *m_tauExt = nullptr;
    QLabel *m_counts = nullptr;
    QLabel *m_published = nullptr;
    RobotSideView *m_robotSide = nullptr;     //!< the wrenches' age, delays and losses
    PassivityView *m_passivityView = nullptr; //!< the energy at the knob's port, the warning
};

} // namespace hatpic
