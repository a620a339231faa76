#include "window/shortcutsdialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QTabWidget>
#include <QTableWidget>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

#include <algorithm>

namespace hatpic {

namespace {

QString actionName(const QAction *action)
{
    const QVariant name = action->property(ShortcutsDialog::kNameProperty);
    QString text = name.isValid() ? name.toString() : action->text();
    text.remove(u'&');
    if (text.endsWith(u'…'))
        text.chop(1);
    return text;
}

} // namespace

void ShortcutsDialog::setName(QAction *action, const QString &name)
{
    action->setProperty(kNameProperty, name);
}

QStringList ShortcutsDialog::describe(const QList<QAction *> &actions)
{
    QStringList lines;
    for (const QAction *action : actions) {
        const QList<QKeySequence> keys = action->shortcuts();
        if (keys.isEmpty())
            continue;
        QStringList texts;
        for (const QKeySequence &key : keys)
            texts << key.toString(QKeySequence::NativeText);
        lines << texts.join(QStringLiteral(" or ")) % u'\t' % actionName(action);
    }
    return lines;
}

ShortcutsDialog::ShortcutsDialog(const QList<QAction *> &actions, QWidget *parent) : QDialog(parent)
{
    setWindowTitle(tr("Help"));
    const QStringList lines = describe(actions);
    // Two tables side by side, so that every shortcut is in view without scrolling.
    auto *shortcuts = new QWidget(this);
    auto *columns = new QHBoxLayout(shortcuts);
    const qsizetype half = (lines.size() + 1) / 2;
    int tallest = 0;
    for (const QStringList &part : {lines.mid(0, half), lines.mid(half)}) {
        auto *table = new QTableWidget(int(part.size()), 2, shortcuts);
        table->setHorizontalHeaderLabels({tr("Keys"), tr("Action")});
        table->verticalHeader()->hide();
        table->setEditTriggers(QAbstractItemView::NoEditTriggers);
        table->setSelectionMode(QAbstractItemView::NoSelection);
        for (int row = 0; row < part.size(); ++row) {
            const QStringList cells = part[row].split(u'\t');
            table->setItem(row, 0, new QTableWidgetItem(cells.value(0)));
            table->setItem(row, 1, new QTableWidgetItem(cells.value(1)));
        }
        table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
        table->horizontalHeader()->setStretchLastSection(true);
        const int rows = table->verticalHeader()->length() +
                         table->horizontalHeader()->sizeHint().height() + 2 * table->frameWidth();
        tallest = std::max(tallest, rows);
        columns->addWidget(table);
    }
    for (QTableWidget *table : shortcuts->findChildren<QTableWidget *>())
        table->setMinimumHeight(std::min(tallest, 700));

    // The user guide ships inside the program (a resource), images and all.
    auto *guide = new QTextBrowser(this);
    guide->setObjectName(QStringLiteral("userGuide"));
    guide->setSearchPaths({QStringLiteral(":/docs")});
    guide->setOpenExternalLinks(true);
    guide->setSource(QUrl(QStringLiteral("qrc:/docs/user-guide.md")),
                     QTextDocument::MarkdownResource);

    auto *tabs = new QTabWidget(this);
    tabs->addTab(shortcuts, tr("Keyboard shortcuts"));
    tabs->addTab(guide, tr("User guide"));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(tabs);
    layout->addWidget(buttons);
    resize(900, 640);
}

} // namespace hatpic
