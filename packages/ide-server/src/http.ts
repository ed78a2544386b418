// @maa/ide-server/http: the HTTP pieces of maa-ide other servers of the project reuse (the lab
// server, docs/lab.md): JSON answers and errors, bounded request bodies, cookies and secrets, the
// Host/Origin admission check.
// Importing this entry loads none of the IDE (no language server, no simulator).
export { HostOriginCheck, readCookie, sameSecret } from './access.js';
export {
    HttpError,
    type Redact,
    readBody,
    readJsonObject,
    requireString,
    sendError,
    sendJson,
    sendText,
} from './http-util.js';
export { contentType, StaticApp } from './static.js';
