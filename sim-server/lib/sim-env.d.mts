/** This package's folder: pyproject.toml and src/maa_sim/ (sim-server/ in a clone). */
export declare const packageDir: string;
/** The development venv's maa-sim (a clone with `bash sim-server/scripts/setup_env.sh` run). */
export declare function developmentMaaSim(dir?: string): string;
/** The folder of cached venvs: $MAA_CACHE_DIR, else $XDG_CACHE_HOME/maa, else ~/.cache/maa. */
export declare function cacheDir(env?: NodeJS.ProcessEnv): string;
/** A hash of what pip installs (pyproject.toml and src/maa_sim). */
export declare function sourcesHash(dir?: string): string;
/** The cached venv for these sources (it may not exist yet). */
export declare function cachedVenv(env?: NodeJS.ProcessEnv, dir?: string): string;
export interface EnsureMaaSimOptions {
    env?: NodeJS.ProcessEnv;
    /** Python 3.11+ for the venv (default: $MAA_PYTHON or python3). */
    python?: string;
    /** Receives the progress lines of a first-use install (default: stderr). */
    onProgress?: (line: string) => void;
    /** The folder with pyproject.toml and src/maa_sim (default: this package's). */
    dir?: string;
    /** maa-sim's pip extras the venv must have, e.g. `['grade']` (Ray, for the grading driver; default none). */
    extras?: readonly string[];
}
/**
 * The maa-sim to run, installing it first when needed: $MAA_SIM when set, else the development
 * venv's when it exists, else the cached venv's (created on first use).
 */
export declare function ensureMaaSim(options?: EnsureMaaSimOptions): Promise<string>;
