#!/usr/bin/env python3
"""Writes protocol/openapi.json: the REST API (paths below) with every shape copied from
messages.schema.json's $defs, converted from JSON Schema 2020-12 to OpenAPI 3.0 schema
objects (const -> enum, type arrays -> nullable/oneOf, numeric exclusiveMinimum -> boolean).

Run after changing messages.schema.json or the REST API:  python3 protocol/make-openapi.py
tests/server/TestSchemaValidator.cpp checks that the two files agree."""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
schema = json.load(open(os.path.join(HERE, "messages.schema.json")))


def convert(s):
    if isinstance(s, list):
        return [convert(x) for x in s]
    if not isinstance(s, dict):
        return s
    out = {}
    for key, value in s.items():
        if key in ("$schema", "$id", "$comment", "examples") or key.startswith("x-"):
            continue
        if key == "$ref":
            out["$ref"] = value.replace("#/$defs/", "#/components/schemas/")
        elif key == "const":
            out["enum"] = [value]
        elif key == "exclusiveMinimum":
            out["minimum"] = value
            out["exclusiveMinimum"] = True
        elif key in ("properties", "$defs"):
            out[key] = {k: convert(v) for k, v in value.items()}
        else:
            out[key] = convert(value)
    types = out.get("type")
    if isinstance(types, list):
        del out["type"]
        if "null" in types:
            out["nullable"] = True
            types = [t for t in types if t != "null"]
        if len(types) == 1:
            out["type"] = types[0]
        else:
            string_keys = {k: out.pop(k) for k in ("minLength", "maxLength", "pattern") if k in out}
            out["oneOf"] = [dict({"type": t}, **(string_keys if t == "string" else {})) for t in types]
    return out


components = {name: convert(d) for name, d in schema["$defs"].items()}


def ref(name):
    return {"$ref": "#/components/schemas/" + name}


def json_body(name, description=None):
    body = {"required": True, "content": {"application/json": {"schema": ref(name)}}}
    if description:
        body["description"] = description
    return body


def ok(description, name=None, status="200"):
    r = {"description": description}
    if name:
        r["content"] = {"application/json": {"schema": ref(name) if isinstance(name, str) else name}}
    return {status: r}


def errors(*statuses):
    texts = {"400": "bad_request, bad_json, schema_violation, invalid_model, invalid_parameter, ...",
             "401": "unauthorized (missing, unknown or expired token)",
             "403": "forbidden (role may not do this) or account_disabled (login of a disabled account)",
             "404": "not_found (also for objects of others the caller may not read)",
             "409": "conflict", "413": "payload_too_large", "429": "rate_limited or limit_exceeded",
             "503": "busy (too many logins or password changes wait for a hashing thread; Retry-After: 1)",
             "507": "storage_full (the server's disk is full: deleting still works)"}
    return {s: {"description": texts[s], "content": {"application/json": {"schema": ref("ErrorBody")}}}
            for s in statuses}


def op(summary, responses, body=None, params=None, public=False, tag=None):
    o = {"summary": summary, "responses": responses}
    if tag:
        o["tags"] = [tag]
    if body:
        o["requestBody"] = body
    if params:
        o["parameters"] = params
    if public:
        o["security"] = []
    return o


ID = {"name": "id", "in": "path", "required": True, "schema": {"type": "integer", "minimum": 1}}
HMF = {"application/xml": {"schema": {"type": "string", "description": ".hmf model file text"}}}

paths = {
    "/health": {"get": op("Liveness check", ok("Server is up", "HealthResponse"), public=True, tag="meta")},
    "/openapi.json": {"get": op("This document", ok("OpenAPI 3.0 document", {"type": "object"}),
                                public=True, tag="meta")},
    "/auth/login": {"post": op("Log in; returns a bearer token",
                               {**ok("Logged in", "LoginResponse"), **errors("400", "401", "429", "503")},
                               body=json_body("LoginRequest"), public=True, tag="auth")},
    "/auth/logout": {"post": op("Revoke the token used", {"204": {"description": "Logged out"},
                                                          **errors("401")}, tag="auth")},
    "/auth/me": {"get": op("The logged-in user", {**ok("The user", "User"), **errors("401")}, tag="auth")},
    "/auth/password": {"post": op("Change the own password (new one at least 8 characters)",
                                  {"204": {"description": "Changed"}, **errors("400", "401", "503")},
                                  body=json_body("PasswordChange"), tag="auth")},
    "/users": {
        "get": op("List users (admin)", {**ok("Users", {"type": "array", "items": ref("User")}),
                                         **errors("401", "403")}, tag="users"),
        "post": op("Create a user (admin); names are unique regardless of case",
                   {**ok("Created", "User", "201"), **errors("400", "401", "403", "409", "503")},
                   body=json_body("UserCreate"), tag="users")},
    "/users/{id}": {
        "patch": op("Change a user's role and/or disable or re-enable the account (admin); the last "
                    "enabled administrator cannot be disabled or demoted (409)",
                    {**ok("Updated", "User"), **errors("400", "401", "403", "404", "409")},
                    body=json_body("UserUpdate"), params=[ID], tag="users")},
    "/auth/download-link": {"post": op(
        "A short-lived signed link for one GET target of the caller's (e.g. results as CSV), for "
        "downloads a browser starts itself; the only REST use of the query string for authentication",
        {**ok("The link", "DownloadLink"), **errors("400", "401")}, body=json_body("DownloadLinkRequest"),
        tag="auth")},
    "/tokens": {
        "get": op("The caller's API tokens, newest first (never their text)",
                  {**ok("Tokens", "TokenList"), **errors("401")}, tag="auth"),
        "post": op("Create a personal API token for scripts (Authorization: Bearer tlmh_...; never in a URL); "
                   "the response is the only time its text is shown; at most 50 per user",
                   {**ok("Created", "TokenCreated", "201"), **errors("400", "401", "429")},
                   body=json_body("TokenCreate"), tag="auth")},
    "/tokens/{id}": {
        "delete": op("Revoke one of the caller's API tokens at once (its open WebSockets end)",
                     {"204": {"description": "Revoked"}, **errors("401", "404")}, params=[ID], tag="auth")},
    "/stats": {"get": op("Transport gauges (admin)", {**ok("Gauges", "ServerStats"), **errors("401", "403")},
                         tag="meta")},
    "/models": {
        "get": op("Models visible to the caller (own and examples; admin all; teacher also students')",
                  {**ok("Model summaries", {"type": "array", "items": ref("ModelSummary")}), **errors("401")},
                  tag="models"),
        "post": op("Create a model: .hmf text (application/xml, name from ?name= or the file's root "
                   "system), or JSON {name, hmf?} (no hmf: empty model) or {name, copy_of}",
                   {**ok("Created", "ModelSummary", "201"), **errors("400", "401", "404", "413", "429")},
                   body={"required": True, "content": {**HMF, "application/json": {"schema": ref("ModelCreate")}}},
                   params=[{"name": "name", "in": "query", "required": False, "schema": {"type": "string"}}],
                   tag="models")},
    "/models/{id}": {
        "get": op("A model: JSON summary plus ModelJson, or the stored .hmf text with ?format=hmf or "
                  "Accept: application/xml",
                  {"200": {"description": "The model",
                           "content": {"application/json": {"schema": ref("ModelDetail")}, **HMF}},
                   **errors("401", "404")},
                  params=[ID, {"name": "format", "in": "query", "required": False,
                               "schema": {"type": "string", "enum": ["json", "hmf"]}}], tag="models"),
        "put": op("Replace the .hmf (application/xml) or rename and/or replace (JSON)",
                  {**ok("Updated", "ModelSummary"), **errors("400", "401", "404", "413")},
                  body={"required": True, "content": {**HMF, "application/json": {"schema": ref("ModelUpdate")}}},
                  params=[ID], tag="models"),
        "delete": op("Delete a model", {"204": {"description": "Deleted"}, **errors("401", "404")},
                     params=[ID], tag="models")},
    "/components": {"get": op("The component catalogue", {**ok("Catalogue", "Catalogue"), **errors("401")},
                              tag="models")},
    "/jobs": {
        "get": op("The caller's jobs", {**ok("Jobs", {"type": "array", "items": ref("JobInfo")}), **errors("401")},
                  tag="jobs"),
        "post": op("Queue a simulation of a stored model or of .hmf text",
                   {**ok("Queued", "JobCreated", "201"), **errors("400", "401", "404", "413", "429")},
                   body=json_body("JobRequest"), tag="jobs")},
    "/jobs/{id}": {
        "get": op("A job", {**ok("The job", "JobInfo"), **errors("401", "404")}, params=[ID], tag="jobs"),
        "delete": op("Cancel a queued or running job (200 with the job); delete a finished one with its results (204)",
                     {**ok("The job", "JobInfo"), "204": {"description": "Deleted"}, **errors("401", "403", "404")},
                     params=[ID], tag="jobs")},
    "/jobs/{id}/rerun": {"post": op("A new job with the same input", {**ok("Queued", "JobCreated", "201"),
                                                                      **errors("401", "404", "429")},
                                    params=[ID], tag="jobs")},
    "/jobs/{id}/results": {"get": op(
        "Logged results: CSV as tlmhub-cli run --csv (header time,<Comp#Port#Var>..., %.17g) or JSON",
        {"200": {"description": "Results",
                 "content": {"application/json": {"schema": ref("ResultsJson")},
                             "text/csv": {"schema": {"type": "string"}}}},
         **errors("400", "401", "404")},
        params=[ID, {"name": "format", "in": "query", "required": False,
                     "schema": {"type": "string", "enum": ["csv", "json"]}},
                {"name": "variables", "in": "query", "required": False,
                 "description": "Comma-separated variable names; all when absent",
                 "schema": {"type": "string"}}], tag="jobs")},
    "/studies": {
        "get": op("The caller's studies, newest first", {**ok("Studies", "StudyList"), **errors("401")}, tag="studies"),
        "post": op("Queue a study: a sweep, a sensitivity analysis or an optimisation of one model (docs/studies.md)",
                   {**ok("Queued", "StudyCreated", "201"), **errors("400", "401", "404", "413", "429")},
                   body=json_body("StudyCreate"), tag="studies")},
    "/studies/{id}": {
        "get": op("A study", {**ok("The study", "StudyInfo"), **errors("401", "404")}, params=[ID], tag="studies"),
        "delete": op("Cancel a queued or running study (200 when cancelled, 202 while its runs stop); delete a "
                     "finished one with its runs (204)",
                     {**ok("The study", "StudyInfo"), "202": {"description": "Cancelling"},
                      "204": {"description": "Deleted"}, **errors("401", "404")}, params=[ID], tag="studies")},
    "/studies/{id}/results": {"get": op(
        "The table of runs finished so far: run, ok, parameters, outputs[, objective]; CSV (%.17g) or JSON "
        "{columns, rows, errors}",
        {"200": {"description": "The table", "content": {"application/json": {"schema": {"type": "object"}},
                                                          "text/csv": {"schema": {"type": "string"}}}},
         **errors("400", "401", "404")},
        params=[ID, {"name": "format", "in": "query", "required": False,
                     "schema": {"type": "string", "enum": ["csv", "json"]}}], tag="studies")},
    "/studies/{id}/runs/{index}/results": {"get": op(
        "A run's whole result, kept with outputs.full; the CSV is byte-identical to tlmhub-cli run --csv --param",
        {"200": {"description": "Results", "content": {"application/json": {"schema": ref("ResultsJson")},
                                                        "text/csv": {"schema": {"type": "string"}}}},
         **errors("400", "401", "404")},
        params=[ID, {"name": "index", "in": "path", "required": True, "schema": {"type": "integer", "minimum": 0}},
                {"name": "format", "in": "query", "required": False,
                 "schema": {"type": "string", "enum": ["csv", "json"]}},
                {"name": "variables", "in": "query", "required": False, "schema": {"type": "string"}}],
        tag="studies")},
    "/studies/{id}/bands": {"get": op(
        "A finished sensitivity study's bands per variable: mean, ±1 and ±2 standard deviations over time",
        {"200": {"description": "Bands", "content": {"application/json": {"schema": {"type": "object"}},
                                                      "text/csv": {"schema": {"type": "string"}}}},
         **errors("400", "401", "404", "409")},
        params=[ID, {"name": "format", "in": "query", "required": False,
                     "schema": {"type": "string", "enum": ["csv", "json"]}}], tag="studies")},
    "/ws": {"get": op("WebSocket upgrade for the tlmhub.v1 protocol (see protocol/README.md); a login token "
                      "comes as ?token= (browsers) or Authorization: Bearer, an API token only as "
                      "Authorization: Bearer",
                      {"101": {"description": "Switching protocols"}, **errors("401")},
                      params=[{"name": "token", "in": "query", "required": False, "schema": {"type": "string"}}],
                      tag="websocket")},
}

doc = {
    "openapi": "3.0.3",
    "info": {"title": "tlmhub REST API", "version": "tlmhub.v1",
             "description": "REST API of tlmhub-server. Errors: HTTP status plus ErrorBody. "
                            "Shapes are copied from messages.schema.json by make-openapi.py."},
    "servers": [{"url": "/api/v1"}],
    "security": [{"bearerAuth": []}],
    "paths": paths,
    "components": {"securitySchemes": {"bearerAuth": {"type": "http", "scheme": "bearer"}},
                   "schemas": components},
}

with open(os.path.join(HERE, "openapi.json"), "w") as f:
    json.dump(doc, f, indent=2)
    f.write("\n")
