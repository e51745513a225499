#!/usr/bin/env bash
# Writes fuzz seeds from the examples in protocol/README.md:
#   OUT/ws/NN.json    one WebSocket request each (`<!-- message -->` blocks, replies left out)
#   OUT/ws/session    model.create, then every request, separated by 0x1E (FuzzWebSocket's format)
#   OUT/rest/NN.txt   "METHOD /path\napplication/json\nBODY" for each POST/PUT/PATCH heading,
#                     one per `<!-- rest: X -->` block under it (or an empty body); {id} -> 1
# Usage: readme-seeds.sh README OUT
set -euo pipefail
readme=$1 out=$2
rm -rf "$out" && mkdir -p "$out/ws" "$out/rest"
awk -v out="$out" '
function flush_rest(body) {
    rest++
    file = sprintf("%s/rest/%02d.txt", out, rest)
    printf "%s %s\napplication/json\n%s", method, path, body > file
    close(file)
}
/^### / {
    if (method != "" && !restBlocks) flush_rest("")
    method = ""; restBlocks = 0
    if ($2 ~ /^(POST|PUT|PATCH)$/ && $3 ~ /^\/api\/v1\//) {
        method = $2; path = substr($3, 8); gsub(/\{id\}/, "1", path)
    }
}
/^<!-- message -->$/ { want = "ws"; next }
/^<!-- rest: / { want = (method != "") ? "rest" : ""; next }
/^```json$/ && want != "" { inBlock = 1; block = ""; next }
/^```$/ && inBlock {
    inBlock = 0
    if (want == "ws" && block ~ /"id"/) {
        ws++
        file = sprintf("%s/ws/%02d.json", out, ws)
        printf "%s", block > file; close(file)
        requests[ws] = block
    } else if (want == "rest") {
        restBlocks++
        flush_rest(block)
    }
    want = ""; next
}
inBlock { block = block $0 "\n"; next }
/^<!--/ { want = "" }
END {
    if (method != "" && !restBlocks) flush_rest("")
    file = out "/ws/session"
    printf "{\"id\": 0, \"type\": \"model.create\", \"name\": \"fuzz\"}" > file
    for (i = 1; i <= ws; i++) printf "\036%s", requests[i] > file
    close(file)
}' "$readme"
