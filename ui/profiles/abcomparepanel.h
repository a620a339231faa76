// The A/B comparison: a table of the parameters in which the two slots differ (or of all of
// them), side by side with the difference (in display units), "push on switch", and the door to a
// blind test. Reads the slots from the ProfileController and follows it; edits nothing itself.
#pragma once

#include "profile/profile.h"

#include <QList>
#include <QWidget>

class QCheckBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace hatpic {

class ProfileController;

class AbComparePanel : public QWidget
{
    Q_OBJECT
public:
    //! One row of the table: texts as shown.
    struct Row
    {
        QString parameter; //!< "K_max [N·m/rad]"
        QString a;
        QString b;
        QString delta; //!< B − A; empty when equal; "differs" for a value that is not a number
        bool differs = false;
    };

    explicit AbComparePanel(ProfileController *profiles, QWidget *parent = nullptr);

    //! Every device parameter, effect field and host parameter of `a` and `b`; angles in
    //! degrees when `degrees`.
    static QList<Row> rows(const Profile &a, const Profile &b, bool degrees);

    void setAngleInDegrees(bool degrees);
    QTableWidget *table() const { return m_table; }
    QPushButton *blindButton() const { return m_blind; }

Q_SIGNALS:
    void blindTestRequested();

private:
    void refresh();

    ProfileController *m_profiles;
    bool m_degrees = false;
    QLabel *m_summary = nullptr;
    QTableWidget *m_table = nullptr;
    QCheckBox *m_all = nullptr; //!< every parameter, not only those that differ
    QPushButton *m_blind = nullptr;
};

} // namespace hatpic
