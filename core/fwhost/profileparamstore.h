// fw::ParamStore as a profile file (profile.md): the --state FILE of hatpic-fw-host and
// hatpic-sim. SAVE_PARAMS writes the device block and the effect block atomically, power-up
// reads them. What SAVE_PARAMS does not own (name, notes, host settings, bridge) is kept.
// A device with several knobs keeps knob 1 in FILE and knob k in a profile beside it,
// knobPath(): state.json, state.knob2.json, … (each a whole profile a tuner can open).
#pragma once

#include "firmware/paramstore.h"

#include <QByteArray>
#include <QString>

namespace hatpic {

struct ProfileReadResult;

class ProfileParamStore : public fw::ParamStore
{
public:
    //! @param owner the program that saves ("hatpic-fw-host"): a new file's name and notes
    //! @param tauLimit the device's torque limit: a new file's host tau_limit [N·m]
    ProfileParamStore(const QString &path, const QString &owner, double tauLimit);

    //! False without a warning when the file does not exist; false with warning() set when it
    //! cannot be read or parsed. (Whether the block is valid is the device core's call.)
    bool load(std::uint8_t axis, fw::StoredSettings &out) override;
    bool load(fw::StoredSettings &out) { return load(0, out); } //!< knob 1
    //! No file yet: a new profile with the blocks, a name, a note and tau_limit. An existing
    //! profile: only its device block and effects change; each field the device holds as the
    //! same float keeps the file's own value, so a save that changes nothing leaves the
    //! profile as it was. A file this build cannot read whole (not a profile, or keys it does
    //! not know, which rewriting would drop) is not overwritten: false, with failure() set.
    bool save(std::uint8_t axis, const fw::StoredSettings &settings) override;
    bool save(const fw::StoredSettings &settings) { return save(0, settings); } //!< knob 1
    std::string_view failure() const override
    {
        return {m_failure.constData(), std::size_t(m_failure.size())};
    }

    QString path() const { return m_path; }
    //! Where knob `axis` (0 = knob 1) is kept: `path` itself for knob 1, else `path` with
    //! ".knob<axis + 1>" before its suffix.
    static QString knobPath(const QString &path, int axis);
    //! Why the last load() failed; empty when it did not.
    QString warning() const { return m_warning; }
    //! Why save() would fail, as far as can be told without writing (a missing or read-only
    //! folder, a file that would not be overwritten), in one sentence; empty when nothing is
    //! in the way. Said once at start, so that the user learns it before a SAVE_PARAMS.
    QString saveProblem() const;

private:
    //! Why an existing file must not be overwritten; empty when it may be.
    QString refusal(const ProfileReadResult &read) const;

    QString m_path;
    QString m_owner;
    double m_tauLimit;
    QString m_warning;
    QByteArray m_failure; //!< UTF-8, for the LOG frame
};

} // namespace hatpic
