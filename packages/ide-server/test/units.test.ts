import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { platformKind } from '../src/apps.js';
import { checkRelativePath } from '../src/confinement.js';
import { findPackageDir, parseReadyLine } from '../src/sim-session.js';

describe('small parts', () => {
  it('derives a platform kind from its generator names', () => {
    expect(platformKind(['ros2.Components', 'ros2.DataTypes', 'ros2.AutomataBehavior'])).toBe('ros2');
    expect(platformKind(['timesync.Components', 'timesync.DataTypes', 'my.Extra'])).toBe('timesync');
    expect(platformKind([])).toBe('');
  });

  it('checks the syntax of client paths', () => {
    expect(checkRelativePath('a/./b//c.arc')).toEqual(['a', 'b', 'c.arc']);
    for (const bad of ['', '.', '..', 'a/..', '/a', 'C:\\a', 'a\\b', 'a\0b', 'c:/x']) expect(() => checkRelativePath(bad), bad).toThrow();
  });

  it("reads maa-sim's ready line", () => {
    const ready = parseReadyLine('{"event": "ready", "rosbridge": "ws://127.0.0.1:4001", "viser": "http://127.0.0.1:4002"}');
    expect(ready?.rosbridge.port).toBe('4001');
    expect(ready?.viser?.origin).toBe('http://127.0.0.1:4002');
    expect(parseReadyLine('{"event": "ready", "rosbridge": "ws://127.0.0.1:4001", "viser": null}')?.viser).toBeUndefined();
    for (const other of ['maa-sim: lockstep mode', '{"event": "finished"}', '{not json', '{"event": "ready", "rosbridge": null}']) {
      expect(parseReadyLine(other), other).toBeUndefined();
    }
  });

  it('finds the folder of a generated package', () => {
    const dir = mkdtempSync(path.join(tmpdir(), 'maa-ide-unit-'));
    try {
      mkdirSync(path.join(dir, 'a_interfaces'));
      mkdirSync(path.join(dir, 'b', 'b'), { recursive: true });
      writeFileSync(path.join(dir, 'b', 'deployment.json'), '{}');
      writeFileSync(path.join(dir, 'lockstep.json'), '{}');
      expect(findPackageDir(dir, 'deployment.json')).toBe(path.join(dir, 'b'));
      expect(findPackageDir(dir, 'lockstep.json')).toBe(dir);
      expect(findPackageDir(dir, 'nothing.json')).toBeUndefined();
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
});
