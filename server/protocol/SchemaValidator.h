#pragma once
// Checks JSON values against the protocol's JSON Schema files (protocol/*.schema.json).
//
// Debian has no C++ JSON Schema validator, so this is our own, for a deliberately small
// subset of JSON Schema 2020-12. The schema files may use only these keywords
// (SchemaValidator::unknownKeywords() reports any other; a test enforces it):
//
//   structure    $schema, $id, $defs, $ref ("#/$defs/X", "#", or "<other $id>#/$defs/X")
//   annotations  title, description, $comment, examples, and any keyword starting "x-"
//                (ignored by validation; x-requests maps a WebSocket message type to its
//                request definition, x-replies to its reply data, x-server-messages the
//                type of a server message to its definition)
//   any value    type (a name or an array of names: null, boolean, object, array, number,
//                integer, string; 1.0 counts as an integer), enum, const, oneOf, anyOf
//   objects      properties, required, additionalProperties (false or a schema)
//   arrays       items (one schema for every element), minItems, maxItems
//   numbers      minimum, maximum, exclusiveMinimum (a number)
//   strings      minLength, maxLength (counted in code points), pattern (ECMAScript regex
//                via std::regex, not anchored, as JSON Schema specifies)
//
// $ref may sit beside other keywords; both apply (2020-12 semantics). Errors name the
// JSON path of the offending value and the rule, e.g. "message.pose.x: expected number".
// Only the first failure is reported.
#include <nlohmann/json.hpp>

#include <map>
#include <regex>
#include <string>
#include <vector>

namespace tlmhub::server {

class SchemaValidator {
public:
    // The validator over the schema files compiled into the binary (thread-safe, built once).
    static const SchemaValidator& protocol();

    SchemaValidator() = default;
    // Add one schema document; its "$id" names it for references from other documents.
    // The first document added is the default one for definition look-ups by name.
    // Returns false (and says why) if the document is not an object or a pattern is invalid.
    bool addDocument(nlohmann::json document, std::string& error);

    // WS request: picks the request definition by msg["type"] through x-requests.
    // code = schema_violation | unknown_message_type.
    bool validateMessage(const nlohmann::json& msg, std::string& code, std::string& error) const;
    // A message the server sends (hello, reply, error, event.*), through x-server-messages.
    // For a reply, `replyTo` (the request's type) also checks data against x-replies.
    bool validateServerMessage(const nlohmann::json& msg, const std::string& replyTo,
                               std::string& error) const;
    // REST body by definition name, e.g. "LoginRequest", "JobRequest".
    bool validate(const std::string& definition, const nlohmann::json& value,
                  std::string& error) const;
    // Same, with the name the error path starts with ("body" for validate()).
    bool validateAs(const std::string& definition, const nlohmann::json& value,
                    const std::string& rootName, std::string& error) const;

    bool hasDefinition(const std::string& definition) const;
    // Message types with a request definition (keys of x-requests).
    std::vector<std::string> requestTypes() const;
    // Definition name of a request type's reply data (from x-replies), empty if none.
    std::string replyDefinition(const std::string& requestType) const;

    // Every keyword in any schema position that is outside the subset above, and every
    // $ref that does not resolve, as "<document>#<pointer>: <problem>".
    std::vector<std::string> unknownKeywords() const;

private:
    struct Document {
        std::string id;
        nlohmann::json root;
    };
    struct Where {
        const Document* document;
        const nlohmann::json* schema;
    };

    bool check(const Where& where, const nlohmann::json& value, const std::string& path,
               std::string& error, int depth) const;
    bool checkType(const nlohmann::json& type, const nlohmann::json& value, const std::string& path,
                   std::string& error) const;
    bool checkObject(const Where& where, const nlohmann::json& value, const std::string& path,
                     std::string& error, int depth) const;
    bool checkArray(const Where& where, const nlohmann::json& value, const std::string& path,
                    std::string& error, int depth) const;
    bool checkNumber(const nlohmann::json& schema, const nlohmann::json& value,
                     const std::string& path, std::string& error) const;
    bool checkString(const nlohmann::json& schema, const nlohmann::json& value,
                     const std::string& path, std::string& error) const;
    bool checkAlternatives(const Where& where, const nlohmann::json& value, const std::string& path,
                           std::string& error, int depth) const;
    bool resolve(const Document& from, const std::string& ref, Where& out) const;
    // The definition "Name" ("#/$defs/Name" of any document) or a "#/..." reference.
    bool findDefinition(const std::string& nameOrRef, Where& out) const;
    const nlohmann::json* annotation(const char* key) const;
    void walkForUnknown(const Document& doc, const nlohmann::json& schema, const std::string& pointer,
                        std::vector<std::string>& problems) const;
    bool compilePatterns(const nlohmann::json& schema, std::string& error);

    std::vector<Document> mDocuments;
    // Compiled "pattern" values, keyed by the pattern text.
    std::map<std::string, std::regex> mPatterns;
};

} // namespace tlmhub::server
