// The app's WebSocket to the server, as a page that works over one (the editor, the live
// watch page) opens it: run frames come as binary messages, and a lost socket is opened
// again (another API node behind the proxy may answer) unless the login ended.
import { WsClient, socketUrl, type SocketLike } from '../api/WsClient';
import type { Session } from './Session';

export function appSocket(session: Session): WsClient {
    return new WsClient(() => {
        const socket = new WebSocket(socketUrl(session.token!, location));
        socket.binaryType = 'arraybuffer';   // run frames come as binary messages (RunController)
        return socket as unknown as SocketLike;
    }, {
        // A refused upgrade does not say why, /auth/me does (401 leads to the login page).
        shouldReconnect: async () => {
            try {
                await session.rest.me();
            } catch {
                // the server cannot be reached yet: try the socket anyway
            }
            return session.token !== null;
        },
    });
}
