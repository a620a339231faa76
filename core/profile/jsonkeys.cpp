#include "jsonkeys.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QList>
#include <QSet>

namespace hatpic {

namespace {

struct Level
{
    bool object = false;
    bool expectKey = false; //!< the next string is a key
    QString path;           //!< the container's own path: "" at the top, "device", "a[]"
    QString lastKey;
    QSet<QString> keys;
};

// The text of one JSON string token (quotes included), escapes resolved by Qt's own reader.
QString decodeString(const QByteArray &token)
{
    return QJsonDocument::fromJson('[' + token + ']').array().at(0).toString();
}

QString member(const QString &path, const QString &key)
{
    return path.isEmpty() ? key : path + u'.' + key;
}

} // namespace

QString firstDuplicateKey(const QByteArray &json)
{
    QList<Level> stack;
    for (qsizetype i = 0; i < json.size(); ++i) {
        const char c = json.at(i);
        if (c == '"') {
            qsizetype end = i + 1;
            while (end < json.size() && json.at(end) != '"')
                end += json.at(end) == '\\' ? 2 : 1;
            if (!stack.isEmpty() && stack.last().object && stack.last().expectKey) {
                Level &level = stack.last();
                const QString key = decodeString(json.mid(i, end - i + 1));
                if (level.keys.contains(key))
                    return member(level.path, key);
                level.keys.insert(key);
                level.lastKey = key;
                level.expectKey = false;
            }
            i = end;
        } else if (c == '{' || c == '[') {
            Level level;
            level.object = c == '{';
            level.expectKey = level.object;
            if (!stack.isEmpty()) {
                const Level &outer = stack.last();
                level.path = outer.object ? member(outer.path, outer.lastKey)
                                          : outer.path + QStringLiteral("[]");
            }
            stack.append(std::move(level));
        } else if (c == '}' || c == ']') {
            if (!stack.isEmpty())
                stack.removeLast();
        } else if (c == ',' && !stack.isEmpty() && stack.last().object) {
            stack.last().expectKey = true;
        }
    }
    return {};
}

} // namespace hatpic
