// A raw pseudo-terminal and an optional symlink to its slave: the part of a program that
// pretends to be a serial device (hatpic-sim, hatpic-fw-host, hatpic-servo-sim).
//
// Not thread-safe; the owner decides who reads and writes master().
#pragma once

#include <QString>

#include <array>
#include <cstddef>

namespace hatpic {

class PseudoTerminal
{
public:
    PseudoTerminal() = default;
    ~PseudoTerminal(); //!< close()
    PseudoTerminal(const PseudoTerminal &) = delete;
    PseudoTerminal &operator=(const PseudoTerminal &) = delete;

    //! openpty with both ends raw (cfmakeraw: no echo, no CR/LF translation), the master
    //! non-blocking, both close-on-exec. The slave stays open for the object's life so that the
    //! master never reads EIO or polls readable while no client has the port open. Returns an
    //! empty string on success, else one sentence saying why it failed.
    QString open();
    //! Removes the link (if still ours) and closes both ends.
    void close();
    bool isOpen() const { return m_master >= 0; }

    int master() const { return m_master; } //!< -1 when closed
    int slave() const { return m_slave; }   //!< -1 when closed
    //! The slave's path (e.g. "/dev/pts/3") that a client opens; empty when closed.
    QString slavePath() const { return m_slavePath; }

    //! Creates a symlink at `path` to the slave (made beside it and renamed over, so it is
    //! atomic). An existing symlink there is replaced (left by a killed program: pty numbers
    //! are reused); any other file is refused. Returns an empty string or the error sentence.
    QString createLink(const QString &path);
    //! Removes the link if it still points to this slave (another program may own it now).
    void removeLink();
    //! removeLink() for a process that a fatal signal ends: async-signal-safe (readlink(),
    //! unlink() on names createLink() kept as C strings); the object is left as it is.
    void removeLinkNow() const noexcept;
    QString linkPath() const { return m_linkPath; }

private:
    static constexpr std::size_t kMaxName = 4096; //!< PATH_MAX [bytes]

    int m_master = -1;
    int m_slave = -1;
    QString m_slavePath;
    QString m_linkPath;
    // The same two names for removeLinkNow(), NUL-terminated; empty when there is no link.
    std::array<char, kMaxName> m_linkName{};
    std::array<char, kMaxName> m_slaveName{};
};

} // namespace hatpic
