// What a package.json promises a tarball holds: the files its `bin`, `main` and `exports` name.
// Pure functions (scripts/pack-install.mjs checks every packed public package with them).

/** Every file path (without './') that `bin`, `main` and `exports` of a package.json name. */
export function packedTargets(pkg) {
    const targets = new Set();
    const add = (value) => {
        if (typeof value === 'string') targets.add(value.replace(/^\.\//, ''));
        else if (Array.isArray(value)) for (const v of value) add(v);
        else if (value && typeof value === 'object') for (const v of Object.values(value)) add(v);
    };
    add(typeof pkg.bin === 'string' ? pkg.bin : Object.values(pkg.bin ?? {}));
    add(pkg.main);
    add(pkg.exports);
    return [...targets].sort();
}

/** The targets of `pkg` (see packedTargets) that are not among the packed `files`; a `*` matches one or more characters. */
export function missingPackedTargets(pkg, files) {
    const packed = new Set(files);
    return packedTargets(pkg).filter((target) => {
        if (!target.includes('*')) return !packed.has(target);
        const escaped = target.split('*').map((part) => part.replace(/[.+?^${}()|[\]\\]/g, '\\$&'));
        const pattern = new RegExp(`^${escaped.join('.+')}$`);
        return !files.some((f) => pattern.test(f));
    });
}
