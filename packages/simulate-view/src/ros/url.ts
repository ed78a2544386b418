/** The proxied rosbridge endpoint of the page's origin: `ws(s)://<host>/sim/rosbridge`. Pure. */
export function rosbridgeUrl(location: { protocol: string; host: string }, path = '/sim/rosbridge'): string {
    const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
    const p = path.startsWith('/') ? path : `/${path}`;
    return `${scheme}//${location.host}${p}`;
}
