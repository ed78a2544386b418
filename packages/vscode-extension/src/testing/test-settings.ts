/** The settings of the stream tests (`maa.test.*`), merged into the manifest's configuration (contributions.ts). Pure. */

export const TEST_SETTINGS = {
    'maa.test.python': {
        type: 'string',
        default: '',
        markdownDescription:
            "The Python 3.11+ that runs the stream tests (`maa-gen test --python`). Empty: `maa-gen`'s default, `$MAA_PYTHON` or `python3`.",
    },
} as const;

/** The `--python` of the test runs ('' for the CLI's default). */
export function testPython(get: (key: string) => unknown): string {
    const v = get('maa.test.python');
    return typeof v === 'string' ? v.trim() : '';
}
