// What the device says for people (v2 LOG frames, a legacy device's non-frame lines) on its
// way out of the session: made printable (printableText(), the one rule for foreign text) and
// bounded in rate, so a device that floods its port cannot flood a terminal or a widget.
#pragma once

#include <QObject>
#include <QString>
#include <QTimer>

namespace hatpic {

class DeviceTextGate : public QObject
{
    Q_OBJECT
public:
    //! Lines let through per interval; the rest are counted and told as one summary line.
    static constexpr int kLinesPerInterval = 20;
    static constexpr int kIntervalMs = 1000;

    explicit DeviceTextGate(QObject *parent = nullptr);

    //! One line as the device sent it.
    void feed(const QString &line);
    //! Tells the lines held back so far, if any (the link closes).
    void flush();

Q_SIGNALS:
    //! A printable line for people: the device's, or a summary of the lines held back.
    void line(const QString &text);

private:
    QTimer m_interval;  //!< runs while an interval is open
    int m_passed = 0;   //!< lines let through in this interval
    quint64 m_held = 0; //!< lines held back and not yet told
};

} // namespace hatpic
