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
             "422": "limit_exceeded: the request can never succeed as sent (steps, log samples, runs, a full "
                    "quota, ...; the message names the limit and its flag), or for an FMU the core's code "
                    "(invalid_parameter, invalid_model, ...)",
             "409": "conflict", "410": "gone (a run's results were dropped: --max-unpinned-runs-per-model)",
             "413": "payload_too_large",
             "429": "rate_limited: try again after Retry-After (failed logins, wrong join codes, jobs queued "
                    "or studies running per user)",
             "503": "busy (too many logins or password changes wait for a hashing thread; Retry-After: 1) or "
                    "unavailable (the server lacks what the call needs, e.g. the FMU runtime library)",
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
USER_ID = {"name": "user_id", "in": "path", "required": True, "schema": {"type": "integer", "minimum": 1}}
IDEMPOTENCY_KEY = {"name": "Idempotency-Key", "in": "header", "required": False,
                   "schema": {"type": "string", "minLength": 1, "maxLength": 200},
                   "description": "Makes the submit safe to send again: the same key and body within 24 h answer "
                                  "what the first request made (protocol/README.md, 'Retrying a submit')"}
FORMAT = {"name": "format", "in": "query", "required": False, "schema": {"type": "string", "enum": ["csv", "json"]}}
FMU_QUERY = [{"name": "parameters", "in": "query", "required": False,
              "description": "Comma-separated component parameters to offer as FMU parameters (Comp.param)",
              "schema": {"type": "string"}},
             {"name": "identifier", "in": "query", "required": False,
              "description": "The FMU's modelIdentifier (default: from the model name)",
              "schema": {"type": "string"}}]
ANY = {"type": "object"}
# An assignment; `warnings` only in its teacher's replies (AssignmentWarning).
ASSIGNMENT = {"type": "object", "properties": {"warnings": {"type": "array", "items": ref("AssignmentWarning")}}}
HMF = {"application/xml": {"schema": {"type": "string", "description": ".hmf model file text"}}}

paths = {
    "/health": {"get": op("Liveness check", ok("Server is up", "HealthResponse"), public=True, tag="meta")},
    "/openapi.json": {"get": op("This document", ok("OpenAPI 3.0 document", {"type": "object"}),
                                public=True, tag="meta")},
    "/auth/login": {"post": op("Log in; returns a bearer token",
                               {**ok("Logged in", "LoginResponse"), **errors("400", "401", "429", "503")},
                               body=json_body("LoginRequest"), public=True, tag="auth")},
    "/auth/providers": {"get": op("How to sign in: the OpenID providers, and whether local passwords log in everyone",
                                  ok("The sign-in methods", "SignInProviders"), public=True, tag="auth")},
    "/auth/oidc/{name}/start": {"get": op("Start a sign-in with an OpenID provider: a redirect to it (302), or "
                                          "back to the app (303) when it cannot be asked now",
                                          {"302": {"description": "To the provider"},
                                           "303": {"description": "To the app's #/sign-in-failed/CODE"}, **errors("404")},
                                          public=True, tag="auth")},
    "/auth/oidc/{name}/callback": {"get": op(
        "The provider's answer (code, state, iss, or error): a redirect (303) to the app with a one-time key "
        "(#/signed-in/KEY) or the reason (#/sign-in-failed/CODE)",
        {"303": {"description": "To the app"}}, public=True, tag="auth")},
    "/auth/oidc/collect": {"post": op("Trade a provider sign-in's one-time key for the login (once, within a minute)",
                                      {**ok("Logged in", "LoginResponse"), **errors("400", "401")},
                                      body=json_body("SignInCollect"), public=True, tag="auth")},
    "/auth/logout": {"post": op("Revoke the token used", {"204": {"description": "Logged out"},
                                                          **errors("401")}, tag="auth")},
    "/auth/me": {"get": op("The logged-in user, with their stored bytes and quota",
                           {**ok("The user", "CurrentUser"), **errors("401")}, tag="auth")},
    "/auth/password": {"post": op("Change the own password (new one at least 8 characters)",
                                  {"204": {"description": "Changed"}, **errors("400", "401", "503")},
                                  body=json_body("PasswordChange"), tag="auth")},
    "/preferences": {
        "get": op("The caller's own settings: the display unit chosen per quantity",
                  {**ok("The settings", "Preferences"), **errors("401")}, tag="auth"),
        "put": op("Replace the caller's own settings (at most 100 units, names and units of 1 to 40 characters)",
                  {**ok("The settings stored", "Preferences"), **errors("400", "401")},
                  body=json_body("Preferences"), tag="auth")},
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
        "A short-lived signed link for one GET download target of the caller's (results, a model's file, "
        "an FMU, a gradebook, a hand-in's model), for downloads a browser starts itself; it ends with the "
        "login it was made in; the only REST use of the query string for authentication; "
        "403 for an API token (send the header instead)",
        {**ok("The link", "DownloadLink"), **errors("400", "401", "403")}, body=json_body("DownloadLinkRequest"),
        tag="auth")},
    "/tokens": {
        "get": op("The caller's API tokens, newest first (never their text)",
                  {**ok("Tokens", "TokenList"), **errors("401")}, tag="auth"),
        "post": op("Create a personal API token for scripts (Authorization: Bearer tlmh_...; never in a URL); "
                   "the response is the only time its text is shown; at most 50 per user",
                   {**ok("Created", "TokenCreated", "201"), **errors("400", "401", "422")},
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
    "/models/{id}/fmu/interface": {"get": op(
        "The interface the model's FMU would have (docs/fmu.md): variables with value references, "
        "power ports, default experiment; 422 with the core's code when the model has none",
        {**ok("The interface", "FmuInterface"), **errors("401", "404", "422")},
        params=[ID, *FMU_QUERY], tag="models")},
    "/models/{id}/fmu": {"get": op(
        "The model as an FMI 2.0 co-simulation FMU for linux64 (application/zip, attachment "
        "<model_identifier>.fmu); 503 unavailable when the server has no FMU runtime library",
        {"200": {"description": "The FMU", "content": {"application/zip": {"schema": {"type": "string", "format": "binary"}}}},
         **errors("401", "404", "422", "503")},
        params=[ID, *FMU_QUERY], tag="models")},
    "/components": {"get": op("The component catalogue", {**ok("Catalogue", "Catalogue"), **errors("401")},
                              tag="models")},
    "/jobs": {
        "get": op("The caller's jobs, newest first; with model_id, the model's run history (the runs the caller "
                  "may see, each with owner and parameters), a page at a time",
                  {**ok("Jobs", {"type": "array", "items": ref("JobInfo")}), **errors("400", "401", "404")},
                  params=[{"name": "model_id", "in": "query", "required": False, "schema": {"type": "integer", "minimum": 1},
                           "description": "Only this model's runs: all of them for an administrator and for the staff "
                                          "of a student's copy, else the caller's own"},
                          {"name": "limit", "in": "query", "required": False,
                           "schema": {"type": "integer", "minimum": 1, "maximum": 100, "default": 20},
                           "description": "With model_id: runs per page"},
                          {"name": "before", "in": "query", "required": False, "schema": {"type": "integer", "minimum": 1},
                           "description": "With model_id: only runs with a lower id (the next page: the last id of this one)"}],
                  tag="jobs"),
        "post": op("Queue a simulation of a stored model or of .hmf text",
                   {**ok("Queued", "JobCreated", "201"), **errors("400", "401", "403", "404", "410", "413", "422", "429", "503")},
                   body=json_body("JobRequest"), params=[IDEMPOTENCY_KEY], tag="jobs")},
    "/jobs/{id}": {
        "get": op("A job", {**ok("The job", "JobInfo"), **errors("401", "404")}, params=[ID], tag="jobs"),
        "patch": op("Name or pin a run (the owner): a pinned run keeps its results",
                    {**ok("The job", "JobInfo"), **errors("400", "401", "403", "404")},
                    body=json_body("JobUpdate"), params=[ID], tag="jobs"),
        "delete": op("Cancel a queued or running job (200 with the job); delete a finished one with its results (204)",
                     {**ok("The job", "JobInfo"), "204": {"description": "Deleted"}, **errors("401", "403", "404")},
                     params=[ID], tag="jobs")},
    "/jobs/{id}/rerun": {"post": op("A new job with the same input", {**ok("Queued", "JobCreated", "201"),
                                                                      **errors("401", "404", "422", "429")},
                                    params=[ID], tag="jobs")},
    "/jobs/{id}/results": {"get": op(
        "Logged results: CSV as tlmhub-cli run --csv (header time,<Comp#Port#Var>..., %.17g) or JSON",
        {"200": {"description": "Results",
                 "content": {"application/json": {"schema": ref("ResultsJson")},
                             "text/csv": {"schema": {"type": "string"}}}},
         **errors("400", "401", "404", "409", "410")},
        params=[ID, {"name": "format", "in": "query", "required": False,
                     "schema": {"type": "string", "enum": ["csv", "json"]}},
                {"name": "variables", "in": "query", "required": False,
                 "description": "Comma-separated variable names; all when absent",
                 "schema": {"type": "string"}}], tag="jobs")},
    "/jobs/{id}/variables": {"get": op(
        "The run's logged variables with their units, without their data (does not use up a keep: false run)",
        {"200": {"description": "Variables", "content": {"application/json": {"schema": {
            "type": "object", "required": ["variables"],
            "properties": {"variables": {"type": "array", "items": {
                "type": "object", "required": ["name", "unit"],
                "properties": {"name": {"type": "string"}, "unit": {"type": "string"}}}}}}}}},
         **errors("401", "404", "409", "410")},
        params=[ID], tag="jobs")},
    "/studies": {
        "get": op("The caller's studies, newest first", {**ok("Studies", "StudyList"), **errors("401")}, tag="studies"),
        "post": op("Queue a study: a sweep, a sensitivity analysis or an optimisation of one model (docs/studies.md)",
                   {**ok("Queued", "StudyCreated", "201"), **errors("400", "401", "403", "404", "410", "413", "422", "429", "503")},
                   body=json_body("StudyCreate"), params=[IDEMPOTENCY_KEY], tag="studies")},
    "/studies/{id}": {
        "get": op("A study", {**ok("The study", "StudyInfo"), **errors("401", "404")}, params=[ID], tag="studies"),
        "delete": op("Cancel a queued or running study (200 when cancelled, 202 while its runs stop); delete a "
                     "finished one with its runs (204)",
                     {**ok("The study", "StudyInfo"), "202": {"description": "Cancelling"},
                      "204": {"description": "Deleted"}, **errors("401", "404")}, params=[ID], tag="studies")},
    "/studies/{id}/resume": {"post": op(
        "Queue an interrupted or cancelled study again from its stored request and model text; it runs only the "
        "runs it lacks (an optimisation walks on from its stored runs to the trace an uninterrupted one gives)",
        {**ok("The study, queued", "StudyInfo", "202"), **errors("401", "404", "409", "429")},
        params=[ID], tag="studies")},
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
    # Teaching labs (docs/labs.md): classes, assignments, copies, checks, hand-ins.
    "/classes": {
        "get": op("The caller's classes with their role in each (admin: all)", {**ok("Classes", ANY), **errors("401")},
                  tag="labs"),
        "post": op("Create a class (server role teacher or admin); the caller becomes its teacher",
                   {**ok("The class with its join code", ANY, "201"), **errors("400", "401", "403")},
                   body=json_body("ClassCreate"), tag="labs")},
    "/classes/join": {"post": op(
        "Join a class as a student with its code; 10 wrong codes in 10 minutes per account (100 per address): 429",
        {**ok("The class", ANY), **errors("400", "401", "404", "409", "429")}, body=json_body("ClassJoin"), tag="labs")},
    "/classes/{id}": {
        "get": op("A class the caller is a member of (staff: with its members)", {**ok("The class", ANY),
                                                                                 **errors("401", "404")},
                  params=[ID], tag="labs"),
        "patch": op("Rename or (un)archive a class (its teacher); an archived class is read-only",
                    {**ok("The class", ANY), **errors("400", "401", "403", "404", "409")},
                    body=json_body("ClassUpdate"), params=[ID], tag="labs"),
        "delete": op("Delete a class with its assignments and hand-ins (its teacher)",
                     {"204": {"description": "Deleted"}, **errors("401", "403", "404")}, params=[ID], tag="labs")},
    "/classes/{id}/import": {"post": op(
        "Add accounts as students from a list of user names (text/csv, one per line); new accounts get a "
        "generated password shown only in this reply",
        {**ok("{accounts: [{username, id, created, password?, error?}]}", ANY), **errors("400", "401", "403", "404", "409")},
        body={"required": True, "content": {"text/csv": {"schema": {"type": "string"}}}}, params=[ID], tag="labs")},
    "/classes/{id}/members/{user_id}": {
        "put": op("Add a member or change their role (the class's teacher)",
                  {**ok("The class", ANY), **errors("400", "401", "403", "404", "409")},
                  body=json_body("MemberUpdate"), params=[ID, USER_ID], tag="labs"),
        "delete": op("Remove a member; a removed student loses access at once",
                     {"204": {"description": "Removed"}, **errors("401", "403", "404", "409")},
                     params=[ID, USER_ID], tag="labs")},
    "/classes/{id}/gradebook": {"get": op(
        "The gradebook: a row per student, a column per assignment (grade, else the latest hand-in's score); CSV "
        "cells are neutralised against formula injection",
        {"200": {"description": "Gradebook", "content": {"text/csv": {"schema": {"type": "string"}},
                                                         "application/json": {"schema": ANY}}},
         **errors("400", "401", "403", "404")},
        params=[ID, FORMAT], tag="labs")},
    "/classes/{id}/live": {"get": op(
        "The live sessions shared with the class on this node (live.share), for its members to watch read-only "
        "with live.subscribe: {sessions: [{session_id, model_name, teacher: {id, username}}]}",
        {**ok("{sessions}", ANY), **errors("401", "404")}, params=[ID], tag="labs")},
    "/classes/{id}/assignments": {
        "get": op("The class's assignments (students: the opened ones, with their status and copy)",
                  {**ok("{assignments}", ANY), **errors("401", "404")}, params=[ID], tag="labs"),
        "post": op("Create an assignment from a template model (and a solution model whose run is the reference)",
                   {**ok("The assignment with warnings", ASSIGNMENT, "201"), **errors("400", "401", "403", "404", "409")},
                   body=json_body("AssignmentCreate"), params=[ID], tag="labs")},
    "/assignments/{id}": {
        "get": op("An assignment (its teacher: with warnings)", {**ok("The assignment", ASSIGNMENT), **errors("401", "404")},
                  params=[ID], tag="labs"),
        "patch": op("Change an assignment; a template_model_id publishes a new template version",
                    {**ok("The assignment with warnings", ASSIGNMENT), **errors("400", "401", "403", "404", "409")},
                    body=json_body("AssignmentUpdate"), params=[ID], tag="labs"),
        "delete": op("Delete an assignment with its hand-ins", {"204": {"description": "Deleted"},
                                                              **errors("401", "403", "404")}, params=[ID], tag="labs")},
    "/assignments/{id}/checks": {
        "get": op("The checks (students: pretests in full, the others by name and points)",
                  {**ok("{checks}", ANY), **errors("401", "404")}, params=[ID], tag="labs"),
        "put": op("Replace the checks; curve checks need the solution's reference run",
                  {**ok("{checks}", ANY), **errors("400", "401", "403", "404", "409")},
                  body=json_body("ChecksUpdate"), params=[ID], tag="labs")},
    "/assignments/{id}/open": {"post": op(
        "The student's copy, made from the template on the first call (201)",
        {**ok("{copy}", ANY), **ok("{copy}, made now", ANY, "201"), **errors("401", "403", "404", "409")},
        params=[ID], tag="labs")},
    "/assignments/{id}/reset": {"post": op(
        "Reset the student's copy to the current template", {**ok("{copy}", ANY), **errors("401", "403", "404", "409")},
        params=[ID], tag="labs")},
    "/assignments/{id}/pretest": {"post": op(
        "Run the student's copy on the job queue and judge it by the pretests (202 when the run "
        "has not ended within --lab-wait-seconds: ask its Location again)",
        {**ok("{checks, score, max_score, job_id}", ANY),
         **ok("{job_id, state, location}: still queued or running", ANY, "202"),
         **errors("400", "401", "403", "404", "409", "422", "429")},
        params=[ID], tag="labs")},
    "/assignments/{id}/pretests/{job}": {"get": op(
        "The pretests' outcome of run `job` of the student's copy, or 202 while it is queued or running",
        {**ok("{checks, score, max_score, job_id}", ANY),
         **ok("{job_id, state, location}: still queued or running", ANY, "202"),
         **errors("400", "401", "403", "404", "409")},
        params=[ID, {"name": "job", "in": "path", "required": True, "schema": {"type": "integer", "minimum": 1}}],
        tag="labs")},
    "/assignments/{id}/handin": {"post": op(
        "Hand in the copy: frozen, run and judged by every check; again before the deadline, once late after it",
        {**ok("The hand-in", ANY, "201"), **errors("400", "401", "403", "404", "409", "422")},
        params=[ID], tag="labs")},
    "/assignments/{id}/handins": {"get": op(
        "Hand-ins, newest first (a student: their own; staff: all, or ?student=ID)",
        {**ok("{handins}", ANY), **errors("400", "401", "404")},
        params=[ID, {"name": "student", "in": "query", "required": False, "schema": {"type": "integer"}}], tag="labs")},
    "/assignments/{id}/dashboard": {"get": op(
        "Per student: status, latest run, latest hand-in and score (staff)",
        {**ok("{students}", ANY), **errors("401", "403", "404")}, params=[ID], tag="labs")},
    "/assignments/{id}/overlay": {"get": op(
        "One variable of every student's latest finished run, at most `points` samples each (staff)",
        {**ok("{variable, series}", ANY), **errors("400", "401", "403", "404")},
        params=[ID, {"name": "variable", "in": "query", "required": True, "schema": {"type": "string"}},
                {"name": "points", "in": "query", "required": False,
                 "schema": {"type": "integer", "minimum": 2, "maximum": 10000}}], tag="labs")},
    "/handins/{id}": {"get": op("A hand-in with its check results (its student; staff)",
                                {**ok("The hand-in", ANY), **errors("401", "404")}, params=[ID], tag="labs")},
    "/handins/{id}/model": {"get": op("The hand-in's frozen model", {"200": {"description": "The .hmf", "content": HMF},
                                                                    **errors("401", "404")}, params=[ID], tag="labs")},
    "/handins/{id}/comments": {
        "get": op("Comments on a hand-in (its student; staff)", {**ok("{comments}", ANY), **errors("401", "404")},
                  params=[ID], tag="labs"),
        "post": op("Comment on a hand-in (teacher or assistant)",
                   {**ok("The comment", ANY, "201"), **errors("400", "401", "403", "404", "409")},
                   body=json_body("CommentCreate"), params=[ID], tag="labs")},
    "/handins/{id}/grade": {"put": op(
        "Set or clear the teacher's grade of a hand-in", {**ok("The hand-in", ANY), **errors("400", "401", "403", "404", "409")},
        body=json_body("GradeUpdate"), params=[ID], tag="labs")},
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
