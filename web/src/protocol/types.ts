// The protocol shapes the app uses, re-exported from the generated types
// (src/protocol/generated.ts, from protocol/*.schema.json) under the names the app reads best.
import type { DoneEvent, ErrorReply, FrameEvent, Hello, LiveFrameEvent, LiveStateEvent, Port, ProgressEvent, Reply, ResyncEvent } from './generated';

export type {
    AssignmentWarning, CatalogueEntry, LiveControl, LiveFrameEvent, LiveModelData, LiveRecordedData, LiveSharedData, LiveSpeed, LiveStartedData, LiveState, LiveStateData, LiveStateEvent, LiveValue, Component, Connection, CurveCheckDefinition, DoneEvent, FmuInterface, FmuPowerPort, FmuVariable, FrameEvent, JobInfo, JobState, Model,
    ModelOpenedData, ModelSummary, Param, Port, PortRef, Pose, Preferences, ProgressEvent, ResultsJson, ResyncEvent, SimulationSettings,
    LtiDeepLink, LtiDeepLinkAnswer, LtiDeepLinkPlace, LtiPlatform, LtiPlatformList, LtiPlatformSettings, LtiScoreInfo, LtiScoreList, LtiToolSettings,
    SignInProviders, SysParam, System, SystemPort, User,
} from './generated';

export type HelloMessage = Hello;
export type ErrorMessage = ErrorReply;
/** A reply; data's shape depends on the request. */
export type ReplyMessage = Omit<Reply, 'data'> & { data: Record<string, unknown> };
export type PortKind = Port['kind'];
export type ServerEvent = ProgressEvent | FrameEvent | DoneEvent | ResyncEvent;
/** The events of a live session (docs/live-sessions.md): WsClient.onLive hears them, onEvent does not. */
export type LiveEvent = LiveFrameEvent | LiveStateEvent;
export type ServerMessage = HelloMessage | ReplyMessage | ErrorMessage | ServerEvent | LiveEvent;

