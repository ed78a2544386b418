// `maa-lab serve` (docs/lab.md "Running a lab").
import path from 'node:path';
import { defaults as ideDefaults } from '@maa/ide-server';
import { Command } from 'commander';
import type { OidcSettings } from '../auth/oidc.js';
import { DEFAULT_PORT, startLabServer } from '../http/server.js';
import { DEFAULT_QUOTAS, type QuotaOptions } from '../quotas/index.js';
import { openLabStore, storageFromEnvironment } from '../storage/index.js';
import { defaultGenerateThreads } from '../workspaces/generate-pool.js';
import { DATA_DIR_HELP, DEFAULT_DATA_DIR, LabCliError, type LabIo } from './io.js';

interface ServeOptions {
    port: string;
    host: string;
    dataDir?: string;
    publicUrl?: string;
    trustProxy?: boolean;
    appDir?: string;
    oidcIssuer?: string;
    oidcClientId?: string;
    oidcAllowHttp?: boolean;
    maxSimulations: string;
    maxSimSecondsPerHour: string;
    maxWorkspaceBytes: string;
    maxWorkspaceFiles: string;
    generateThreads?: string;
    rayAddress?: string;
}

/** The environment variable that holds the OpenID Connect client secret (never a command-line argument). */
export const OIDC_SECRET_VARIABLE = 'MAA_LAB_OIDC_CLIENT_SECRET';

/**
 * @param onStarted called with a function that stops the server (tests stop it; the command
 *   itself stops on SIGINT and SIGTERM)
 */
export function serveCommand(io: LabIo, onStarted?: (stop: () => Promise<void>, url: string) => void): Command {
    return withWorkOptions(new Command('serve'))
        .description('start the lab server on the embedded database (--data-dir) or on the PostgreSQL server of DATABASE_URL')
        .option('--port <port>', 'the port to listen on (0: any free port)', String(DEFAULT_PORT))
        .option('--host <address>', 'the address to listen on (0.0.0.0: every interface)', '127.0.0.1')
        .option('--data-dir <dir>', DATA_DIR_HELP)
        .option('--public-url <url>', 'the address students open, e.g. https://lab.example.org behind a reverse proxy')
        .option('--trust-proxy', 'behind a reverse proxy: take the client address from X-Forwarded-For and mark cookies Secure')
        .option('--app-dir <dir>', "the web app to serve: the students' IDE (default: the installed @maa/ide-web's dist/)")
        .option('--oidc-issuer <url>', `single sign-on: the OpenID Connect provider (the client secret comes from ${OIDC_SECRET_VARIABLE})`)
        .option('--oidc-client-id <id>', 'single sign-on: the client id registered at the provider')
        .option('--oidc-allow-http', 'single sign-on: accept a provider on plain http (only for a provider on this machine)')
        .action(async (options: ServeOptions) => {
            const port = Number(options.port);
            if (!Number.isInteger(port) || port < 0 || port > 65535)
                throw new LabCliError(`--port must be a port number, not ${options.port}`);
            if (options.publicUrl !== undefined && !URL.canParse(options.publicUrl))
                throw new LabCliError(`--public-url is not a URL: ${options.publicUrl}`);
            const oidc = oidcSettings(io, options);
            const quotas = quotaSettings(options);
            const generateThreads = threadsSetting(options.generateThreads);
            const dataDir = path.resolve(io.cwd, options.dataDir ?? DEFAULT_DATA_DIR);
            const store = await openLabStore(storageFromEnvironment(io.env, dataDir));
            let server: Awaited<ReturnType<typeof startLabServer>>;
            try {
                server = await startLabServer({
                    store,
                    port,
                    host: options.host,
                    ...(options.publicUrl ? { publicUrl: options.publicUrl } : {}),
                    trustProxy: options.trustProxy === true,
                    appDir: options.appDir ? path.resolve(io.cwd, options.appDir) : ideDefaults.appDir,
                    ...(oidc ? { oidc } : {}),
                    log: (line) => io.err(`maa-lab: ${line}\n`),
                    workspaces: { dataDir, quotas, ...(generateThreads ? { generateThreads } : {}) },
                    ...(options.rayAddress ? { grading: { rayAddress: options.rayAddress } } : {}),
                });
            } catch (e) {
                await store.close();
                throw new LabCliError(`cannot start the server: ${(e as Error).message}`);
            }
            // Runs a stopped server left queued or running end as failed (never stuck).
            const failed = await server.grading.recover();
            if (failed > 0) io.err(`maa-lab: ${failed} grading runs left unfinished by the last server are marked failed\n`);
            io.out(
                `maa-lab serves ${server.publicUrl} (${store.backend === 'pglite' ? 'embedded database' : 'PostgreSQL'}); log in at ${server.publicUrl}/login\n`,
            );
            let stopping: Promise<void> | undefined;
            const stop = () => {
                stopping ??= server.close().then(() => store.close());
                return stopping;
            };
            if (onStarted) onStarted(stop, server.url);
            else {
                process.once('SIGINT', () => void stop());
                process.once('SIGTERM', () => void stop());
            }
        });
}

/** The options of the students' work: quotas, generator threads, the grading's Ray cluster. */
function withWorkOptions(command: Command): Command {
    return command
        .option(
            '--max-simulations <n>',
            'quota: simulations a student may run at the same time',
            String(DEFAULT_QUOTAS.concurrentSimulations),
        )
        .option(
            '--max-sim-seconds-per-hour <n>',
            'quota: simulated seconds a student may run within any hour',
            String(DEFAULT_QUOTAS.simulatedSecondsPerHour),
        )
        .option('--max-workspace-bytes <n>', "quota: the bytes of a workspace's files", String(DEFAULT_QUOTAS.workspaceBytes))
        .option('--max-workspace-files <n>', 'quota: the files of a workspace', String(DEFAULT_QUOTAS.workspaceFiles))
        .option(
            '--generate-threads <n>',
            `the worker threads that run the students' generators (default: the cores but one, 1 to 4; here ${defaultGenerateThreads()})`,
        )
        .option(
            '--ray-address <address>',
            'grading: run the grading tasks on this Ray cluster (default: RAY_ADDRESS, else Ray on this machine)',
        );
}

/** The quota options, each a positive whole number (else a LabCliError naming it). */
function quotaSettings(options: ServeOptions): QuotaOptions {
    const given: Array<[keyof QuotaOptions, string, string]> = [
        ['concurrentSimulations', '--max-simulations', options.maxSimulations],
        ['simulatedSecondsPerHour', '--max-sim-seconds-per-hour', options.maxSimSecondsPerHour],
        ['workspaceBytes', '--max-workspace-bytes', options.maxWorkspaceBytes],
        ['workspaceFiles', '--max-workspace-files', options.maxWorkspaceFiles],
    ];
    const quotas = { ...DEFAULT_QUOTAS };
    for (const [key, flag, text] of given) {
        const value = Number(text);
        if (!/^\d+$/.test(text) || !Number.isSafeInteger(value) || value < 1)
            throw new LabCliError(`${flag} must be a positive whole number, not ${text}`);
        quotas[key] = value;
    }
    return quotas;
}

/** --generate-threads: a whole number from 1 to 64, or undefined (the default) when not given. */
function threadsSetting(text: string | undefined): number | undefined {
    if (text === undefined) return undefined;
    const value = Number(text);
    if (!/^\d+$/.test(text) || value < 1 || value > 64)
        throw new LabCliError(`--generate-threads must be a whole number from 1 to 64, not ${text}`);
    return value;
}

function oidcSettings(io: LabIo, options: ServeOptions): OidcSettings | undefined {
    if (!options.oidcIssuer && !options.oidcClientId) return undefined;
    if (!options.oidcIssuer || !options.oidcClientId) throw new LabCliError('single sign-on needs both --oidc-issuer and --oidc-client-id');
    const secret = io.env[OIDC_SECRET_VARIABLE];
    if (!secret) throw new LabCliError(`single sign-on needs the client secret in the environment variable ${OIDC_SECRET_VARIABLE}`);
    if (!URL.canParse(options.oidcIssuer)) throw new LabCliError(`--oidc-issuer is not a URL: ${options.oidcIssuer}`);
    return { issuer: options.oidcIssuer, clientId: options.oidcClientId, clientSecret: secret, allowHttp: options.oidcAllowHttp === true };
}
