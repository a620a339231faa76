#include "jsonkeys.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QSet>

#include <vector>

namespace hatpic {

namespace {

// One open object or array. No path is kept per level (that cost O(depth² · key length) in a
// deeply nested file): the path of a duplicate is put together from the stack when one is found.
struct Level
{
    bool object = false;
    bool expectKey = false; //!< the next string is a key
    QString lastKey;        //!< an object's latest key: the name of what it holds now
    QSet<QString> keys;     //!< an object's keys so far
};

// The text of one JSON string token (quotes included), escapes resolved by Qt's own reader.
QString decodeString(const QByteArray &token)
{
    return QJsonDocument::fromJson('[' + token + ']').array().at(0).toString();
}

//! "device.K_max", "extra[].a": the path of `key` in the innermost of `stack`.
QString pathOf(const std::vector<Level> &stack, const QString &key)
{
    QString path;
    for (std::size_t i = 0; i + 1 < stack.size(); ++i) {
        if (stack[i].object)
            path += (path.isEmpty() ? QString() : QStringLiteral(".")) + stack[i].lastKey;
        else
            path += QStringLiteral("[]");
    }
    return path.isEmpty() ? key : path + u'.' + key;
}

} // namespace

QString firstDuplicateKey(const QByteArray &json)
{
    std::vector<Level> stack;
    for (qsizetype i = 0; i < json.size(); ++i) {
        const char c = json.at(i);
        if (c == '"') {
            qsizetype end = i + 1;
            while (end < json.size() && json.at(end) != '"')
                end += json.at(end) == '\\' ? 2 : 1;
            if (!stack.empty() && stack.back().object && stack.back().expectKey) {
                Level &level = stack.back();
                QString key = decodeString(json.mid(i, end - i + 1));
                if (level.keys.contains(key))
                    return pathOf(stack, key);
                level.keys.insert(key);
                level.lastKey = std::move(key);
                level.expectKey = false;
            }
            i = end;
        } else if (c == '{' || c == '[') {
            Level level;
            level.object = c == '{';
            level.expectKey = level.object;
            stack.push_back(std::move(level));
        } else if (c == '}' || c == ']') {
            if (!stack.empty())
                stack.pop_back();
        } else if (c == ',' && !stack.empty() && stack.back().object) {
            stack.back().expectKey = true;
        }
    }
    return {};
}

} // namespace hatpic
