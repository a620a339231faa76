#include "profiles/abcomparepanel.h"

#include "model/paramtable.h"
#include "profiles/profilecontroller.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <numbers>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

QString text(std::string_view s)
{
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

QString number(double v)
{
    return QString::number(v, 'g', 6);
}

template<typename Params, std::size_t N>
void addNumbers(QList<AbComparePanel::Row> &rows, const std::array<FieldSpec<Params>, N> &fields,
                const Params &a, const Params &b, bool degrees)
{
    for (const FieldSpec<Params> &f : fields) {
        const double scale = f.angle && degrees ? 180.0 / std::numbers::pi : 1.0;
        const QString unit = f.angle && degrees ? u"°"_s : text(f.unit);
        const double va = a.*f.member * scale;
        const double vb = b.*f.member * scale;
        AbComparePanel::Row row;
        row.parameter = text(f.symbol) + u" ["_s + unit + u']';
        row.a = number(va);
        row.b = number(vb);
        row.differs = a.*f.member != b.*f.member;
        if (row.differs)
            row.delta = (vb > va ? u"+"_s : QString()) + number(vb - va);
        rows << row;
    }
}

QString modeText(ReferenceMode mode)
{
    return mode == ReferenceMode::Rotation ? AbComparePanel::tr("rotation")
                                           : AbComparePanel::tr("translation");
}

} // namespace

AbComparePanel::AbComparePanel(ProfileController *profiles, QWidget *parent)
    : QWidget(parent), m_profiles(profiles)
{
    m_summary = new QLabel(this);
    m_summary->setObjectName(u"ab_summary"_s);
    m_summary->setWordWrap(true);
    m_table = new QTableWidget(0, 4, this);
    m_table->setObjectName(u"ab_differences"_s);
    m_table->setHorizontalHeaderLabels({tr("Parameter"), tr("A"), tr("B"), tr("Δ (B − A)")});
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->setFocusPolicy(Qt::NoFocus);
    // Fits a narrow dock without a horizontal scroll bar: the values share what is left.
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_all = new QCheckBox(tr("All parameters"), this);
    m_all->setObjectName(u"ab_all_parameters"_s);
    m_all->setToolTip(tr("Also list the parameters that are the same in A and B"));
    connect(m_all, &QCheckBox::toggled, this, &AbComparePanel::refresh);

    auto *pushOnSwitch = new QCheckBox(tr("Push on switch"), this);
    pushOnSwitch->setObjectName(u"ab_push_on_switch"_s);
    QAction *action = profiles->pushOnSwitchAction();
    pushOnSwitch->setToolTip(action->toolTip());
    pushOnSwitch->setChecked(action->isChecked());
    connect(pushOnSwitch, &QCheckBox::toggled, action, &QAction::setChecked);
    connect(action, &QAction::toggled, pushOnSwitch, &QCheckBox::setChecked);
    auto *toggle = new QToolButton(this);
    toggle->setDefaultAction(profiles->abToggleAction());
    m_blind = new QPushButton(tr("Blind test…"), this);
    m_blind->setObjectName(u"ab_blind_test"_s);
    m_blind->setToolTip(tr("Present A and B in a random order without saying which is which, "
                           "and record the participant's answers"));
    connect(m_blind, &QPushButton::clicked, this, &AbComparePanel::blindTestRequested);

    auto *buttons = new QHBoxLayout;
    buttons->addWidget(toggle);
    buttons->addWidget(pushOnSwitch);
    buttons->addWidget(m_all);
    buttons->addStretch(1);
    buttons->addWidget(m_blind);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(buttons);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 1);

    connect(profiles, &ProfileController::slotsChanged, this, &AbComparePanel::refresh);
    refresh();
}

QList<AbComparePanel::Row> AbComparePanel::rows(const Profile &a, const Profile &b, bool degrees)
{
    QList<Row> rows;
    addNumbers(rows, kDeviceFields, a.device, b.device, degrees);
    addNumbers(rows, kEffectFields, a.effects, b.effects, degrees);
    addNumbers(rows, kPassivityFields, a.passivity, b.passivity, degrees);
    addNumbers(rows, kHostFields, a.host, b.host, degrees);
    Row mode{tr("mode"), modeText(a.host.mode), modeText(b.host.mode), {}, false};
    mode.differs = a.host.mode != b.host.mode;
    Row deadzone{tr("ref_deadzone"),
                 a.host.ref_deadzone ? tr("on") : tr("off"),
                 b.host.ref_deadzone ? tr("on") : tr("off"),
                 {},
                 false};
    deadzone.differs = a.host.ref_deadzone != b.host.ref_deadzone;
    for (Row *r : {&mode, &deadzone}) {
        if (r->differs)
            r->delta = tr("differs");
        rows << *r;
    }
    return rows;
}

void AbComparePanel::setAngleInDegrees(bool degrees)
{
    m_degrees = degrees;
    refresh();
}

void AbComparePanel::refresh()
{
    const bool both = m_profiles->isSlotUsed(0) && m_profiles->isSlotUsed(1);
    m_blind->setEnabled(both);
    m_table->setEnabled(both);
    if (!both) {
        m_table->setRowCount(0);
        m_summary->setText(tr("Only slot A is loaded. Switch A/B (Ctrl+B) to start B as a copy "
                              "of A, then change B."));
        return;
    }
    const Profile a = m_profiles->slotProfile(0);
    const Profile b = m_profiles->slotProfile(1);
    QList<Row> list = rows(a, b, m_degrees);
    const auto differing =
        std::count_if(list.cbegin(), list.cend(), [](const Row &row) { return row.differs; });
    if (!m_all->isChecked())
        list.removeIf([](const Row &row) { return !row.differs; });
    m_table->setRowCount(int(list.size()));
    for (int r = 0; r < list.size(); ++r) {
        const Row &row = list[r];
        const QString cells[] = {row.parameter, row.a, row.b, row.delta};
        for (int c = 0; c < 4; ++c) {
            auto *item = new QTableWidgetItem(cells[c]);
            if (c > 0)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            QFont font = item->font();
            font.setBold(row.differs);
            item->setFont(font);
            m_table->setItem(r, c, item);
        }
    }
    // One line, so the table keeps its room in a low dock; the title says which slot is edited.
    m_summary->setText(
        tr("%n parameter(s) differ. A: %1, B: %2", "", int(differing)).arg(a.name, b.name));
}

} // namespace hatpic
