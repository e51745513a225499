// One error type for REST and WebSocket failures: the server's stable code and its message.
export class ApiError extends Error {
    constructor(
        readonly code: string,
        message: string,
        readonly status = 0,
    ) {
        super(message);
        this.name = 'ApiError';
    }
}
