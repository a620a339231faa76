// What the tests of the real MainWindow share (tst_mainwindow, tst_mainwindowreplay,
// tst_mainwindowusability): a window of a first launch's size on the offscreen platform, with
// settings of the test's own; its parts by object name; the in-process simulator ("sim")
// connected; fresh samples waited for.
#pragma once

#include "connection/linkstatuswidget.h"
#include "plots/plotfeed.h"
#include "plots/plotpanel.h"
#include "profiles/profilecontroller.h"
#include "window/mainwindow.h"

#include <QCoreApplication>
#include <QMessageBox>
#include <QObject>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <memory>
#include <utility>

namespace hatpic::test {

//! The base of the main window's test classes: its slots make a fresh window for every test
//! function (init) and throw it away after it (cleanup).
class MainWindowTest : public QObject
{
    Q_OBJECT
public:
    //! `applicationName` names the test's own settings (tests may run side by side).
    explicit MainWindowTest(QString applicationName) : m_applicationName(std::move(applicationName))
    {}

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("hatpic-test"));
        QCoreApplication::setApplicationName(m_applicationName);
        QVERIFY(m_dir.isValid());
    }

    void init()
    {
        QSettings().clear();
        m_window = std::make_unique<MainWindow>();
        // The size a first launch gets on a large screen (the offscreen screen is 800×600).
        m_window->resize(1400, 900);
        find<ProfileController>("profileController")->setQuestion([](const QString &) {
            return QMessageBox::Discard;
        });
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    }

    void cleanup() { m_window.reset(); }

protected:
    static constexpr int kConnectMs = 15000; //!< generous: the machine is shared
    static constexpr int kDataMs = 15000;

    static ConnectOptions simOptions(ProtocolChoice protocol = ProtocolChoice::V2)
    {
        ConnectOptions options;
        options.port = QStringLiteral("sim");
        options.protocol = protocol;
        return options;
    }

    //! Samples in the live buffer with a time after t.
    static qsizetype samplesAfter(const SampleBuffer &buffer, double t)
    {
        return buffer.size() - buffer.upperBound(t);
    }

    //! A part of the window by its object name: the window has no getters for its parts.
    template<typename T> static T *part(const QObject *window, const char *name)
    {
        auto *found = window->findChild<T *>(QString::fromLatin1(name));
        if (!found)
            qFatal("the window has no %s named %s", T::staticMetaObject.className(), name);
        return found;
    }

    //! Where the live view ends: the newest sample, or first + window while the data are
    //! shorter. Repaints first, so that nothing arrives between the repaint and the comparison.
    static double liveViewEnd(const MainWindow &window)
    {
        auto *plots = part<PlotPanel>(&window, "plotPanel");
        plots->repaintNow();
        const SampleBuffer &b = part<PlotFeed>(&window, "plotFeed")->liveBuffer();
        return std::max(b.lastTime(), b.firstTime() + plots->windowLength());
    }

    void connectSim(ProtocolChoice protocol = ProtocolChoice::V2)
    {
        m_window->connectTo(simOptions(protocol));
        QTRY_COMPARE_WITH_TIMEOUT(client()->state(), SessionState::Connected, kConnectMs);
        QTRY_VERIFY_WITH_TIMEOUT(client()->deviceTuning().params.has_value() ||
                                     !client()->deviceInfo().canSetParams(),
                                 kConnectMs);
    }

    //! A part of the window by its object name.
    template<typename T> T *find(const char *name) const { return part<T>(m_window.get(), name); }
    DeviceClient *client() const { return find<DeviceClient>("deviceClient"); }
    //! The device's parameters as read (DeviceParams{} until the device has told them).
    DeviceParams deviceParams() const
    {
        return client()->deviceTuning().params.value_or(DeviceParams{});
    }
    LinkStatusWidget *linkStatus() const { return find<LinkStatusWidget>("linkStatus"); }
    const SampleBuffer &liveBuffer() const { return find<PlotFeed>("plotFeed")->liveBuffer(); }

    bool waitForSamples(qsizetype count)
    {
        const double since = liveBuffer().lastTime();
        return QTest::qWaitFor([&] { return samplesAfter(liveBuffer(), since) >= count; }, kDataMs);
    }

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;

private:
    QString m_applicationName;
};

} // namespace hatpic::test
