#include "ros/ros2/typehash.h"

#include <QByteArray>
#include <QCryptographicHash>

#include <set>
#include <string_view>

namespace hatpic::ros::ros2 {

namespace {

// Every type `type` uses, however deep (checkTypeTable() guarantees each is in the table).
void collectReferences(const TypeDef &type, std::set<std::string_view> &into)
{
    for (const FieldDef &field : type.fields) {
        if (field.kind != FieldKind::Nested || !into.insert(field.nestedType).second)
            continue;
        if (const TypeDef *nested = findType(field.nestedType))
            collectReferences(*nested, into);
    }
}

// A JSON string of a name the table allows (checkTypeTable(): [A-Za-z0-9_/], nothing to
// escape).
std::string quoted(std::string_view text)
{
    return '"' + std::string(text) + '"';
}

// IndividualTypeDescription without the fields' default_value:
// {"type_name": …, "fields": [{"name": …, "type": {"type_id": …, "capacity": N,
// "string_capacity": 0, "nested_type_name": …}}, …]}
std::string individual(const TypeDef &type)
{
    std::string out = "{\"type_name\": " + quoted(type.name) + ", \"fields\": [";
    bool first = true;
    for (const FieldDef &field : type.fields) {
        if (!first)
            out += ", ";
        first = false;
        // Unbounded sequences and strings: capacity and string_capacity 0; an array its size.
        out += "{\"name\": " + quoted(field.name) +
               ", \"type\": {\"type_id\": " + std::to_string(field.typeId()) +
               ", \"capacity\": " + std::to_string(field.capacity) +
               ", \"string_capacity\": 0, \"nested_type_name\": " + quoted(field.nestedType) + "}}";
    }
    return out + "]}";
}

} // namespace

std::string hashedTypeDescription(const TypeDef &type)
{
    std::set<std::string_view> references; // std::less on the bytes: Python's sorted()
    collectReferences(type, references);
    std::string out =
        "{\"type_description\": " + individual(type) + ", \"referenced_type_descriptions\": [";
    bool first = true;
    for (const std::string_view name : references) {
        if (!first)
            out += ", ";
        first = false;
        if (const TypeDef *referenced = findType(name))
            out += individual(*referenced);
    }
    return out + "]}";
}

std::string typeHash(const TypeDef &type)
{
    const std::string text = hashedTypeDescription(type);
    const QByteArray digest = QCryptographicHash::hash(
        QByteArrayView(text.data(), qsizetype(text.size())), QCryptographicHash::Sha256);
    return "RIHS01_" + digest.toHex().toStdString();
}

std::string typeHashUserData(const TypeDef &type)
{
    return "typehash=" + typeHash(type) + ";";
}

} // namespace hatpic::ros::ros2
