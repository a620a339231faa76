// A real ROS 1 master for tests: `roscore` on 127.0.0.1 at a free port, with a ROS_HOME and
// log directory of its own, in a process group of its own so that stopping it ends rosmaster
// and rosout too. And the rospy node of ros1peer.py, a ROS 1 client that is not ours.
#pragma once

#include <QJsonObject>
#include <QList>
#include <QObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QTemporaryDir>

#include <memory>

namespace hatpic::test {

class RosCore
{
public:
    //! What the constructor does to this process's environment.
    enum class ThisProcess { Untouched, Exported };
    //! Picks a free port; nothing runs yet. `Exported` calls exportEnvironment() at once, so a
    //! test that declares its RosCore before every member that starts a thread sets the
    //! variables while it has one thread (setenv beside another thread's getenv is undefined
    //! behaviour: a DeviceClient's session thread reads HATPIC_REALTIME as it starts).
    explicit RosCore(ThisProcess thisProcess = ThisProcess::Untouched);
    ~RosCore();
    RosCore(const RosCore &) = delete;
    RosCore &operator=(const RosCore &) = delete;

    int port() const { return m_port; }
    QString uri() const; //!< "http://127.0.0.1:PORT"

    //! `base` with what a ROS 1 program needs to use this master: ROS_MASTER_URI, ROS_IP
    //! 127.0.0.1, ROS_HOME and ROS_LOG_DIR; without ROS_HOSTNAME and ROS_NAMESPACE.
    QProcessEnvironment
    environment(QProcessEnvironment base = QProcessEnvironment::systemEnvironment()) const;
    //! The same environment for this process (before its first ROS 1 node, and before any
    //! other thread starts).
    void exportEnvironment() const;

    //! Starts roscore and waits until the master answers; empty, or why it did not.
    QString start(int timeoutMs = 30000);
    //! SIGINT to its process group, SIGKILL after 10 s; returns when the group is gone.
    void stop();
    bool isRunning() const { return m_pid > 0; }
    //! Whether a master answers getPid at the URI now.
    bool answers() const;
    //! What the master holds for `node` ("/hatpic_bridge"), from its getSystemState (what
    //! `rosnode list` and `rosnode info` read): "publishes /rosout", "subscribes /wrench",
    //! "provides /hatpic_bridge/get_loggers", sorted; empty when it knows nothing of the node.
    //! `*error` says why the master could not be asked (then the list is empty too).
    QStringList registrations(const QString &node, QString *error = nullptr) const;

private:
    int m_port = 0;
    QTemporaryDir m_home;
    std::unique_ptr<QProcess> m_process;
    qint64 m_pid = 0;
};

//! tests/core/ros/ros1peer.py as a child process: what it receives and reports, parsed.
class Ros1Peer : public QObject
{
    Q_OBJECT
public:
    Ros1Peer() = default;
    ~Ros1Peer() override; //!< stop()

    //! Starts the peer with `arguments` (--sub TOPIC=TYPE, --pub …; ros1peer.py's) and waits
    //! until it is ready; empty, or why not.
    QString start(const QProcessEnvironment &environment, const QStringList &arguments,
                  int timeoutMs = 30000);
    void stop();
    //! One command line (ros1peer.py's stdin).
    void send(const QString &line);

    //! Messages received on `topic` so far ({"topic", "callerid", "msg"}), oldest first.
    QList<QJsonObject> received(const QString &topic) const;
    //! Forgets the messages received so far (not the events).
    void clear();
    //! The newest event line of that kind ({"event": kind, …}); empty when none yet.
    QJsonObject lastEvent(const QString &kind) const;
    //! The newest count of subscribers of the peer's publisher of `topic`; -1 before any.
    int connections(const QString &topic) const;
    QString uri() const { return m_uri; }
    QByteArray errors() const { return m_stderr; }

private:
    void read();

    std::unique_ptr<QProcess> m_process;
    QByteArray m_partial;
    QByteArray m_stderr;
    QList<QJsonObject> m_lines;
    QString m_uri;
};

//! The message field at a dotted path ("wrench.force.z", "position.0") as a number; NaN when
//! absent.
double field(const QJsonObject &message, const QString &path);

} // namespace hatpic::test
