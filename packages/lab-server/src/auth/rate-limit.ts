// Login rate limiting: failed logins are counted per login name and per client address in a
// sliding window; past the limit a login is refused (429 with Retry-After) without checking the
// password, until the oldest failure leaves the window.

export interface RateLimitOptions {
    /** failures allowed per login name in the window */
    perLogin: number;
    /** failures allowed per client address in the window */
    perAddress: number;
    windowMs: number;
}

export const DEFAULT_RATE_LIMITS: RateLimitOptions = { perLogin: 5, perAddress: 20, windowMs: 15 * 60 * 1000 };

class Window {
    private readonly failures = new Map<string, number[]>();

    constructor(
        private readonly limit: number,
        private readonly windowMs: number,
    ) {}

    /** Milliseconds until `key` may try again, or 0. */
    blockedFor(key: string, now: number): number {
        const times = this.recent(key, now);
        if (times.length < this.limit) return 0;
        return (times[times.length - this.limit] ?? now) + this.windowMs - now;
    }

    fail(key: string, now: number): void {
        const times = this.recent(key, now);
        times.push(now);
        this.failures.set(key, times);
    }

    clear(key: string): void {
        this.failures.delete(key);
    }

    private recent(key: string, now: number): number[] {
        const times = (this.failures.get(key) ?? []).filter((t) => t > now - this.windowMs);
        if (times.length === 0) this.failures.delete(key);
        return times;
    }
}

export class LoginRateLimiter {
    private readonly logins: Window;
    private readonly addresses: Window;

    constructor(
        options: RateLimitOptions = DEFAULT_RATE_LIMITS,
        private readonly clock: () => number = Date.now,
    ) {
        this.logins = new Window(options.perLogin, options.windowMs);
        this.addresses = new Window(options.perAddress, options.windowMs);
    }

    /** Seconds the caller must wait (for the Retry-After header), or 0 when the attempt may go ahead. */
    retryAfter(login: string, address: string): number {
        const now = this.clock();
        const ms = Math.max(this.logins.blockedFor(login.toLowerCase(), now), this.addresses.blockedFor(address, now));
        return ms > 0 ? Math.ceil(ms / 1000) : 0;
    }

    failed(login: string, address: string): void {
        const now = this.clock();
        this.logins.fail(login.toLowerCase(), now);
        this.addresses.fail(address, now);
    }

    /** A successful login clears its name's failures (not the address's: one good account does not unlock guessing others). */
    succeeded(login: string): void {
        this.logins.clear(login.toLowerCase());
    }
}
