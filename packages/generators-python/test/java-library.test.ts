import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { EmptyFileSystem } from 'langium';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { builtinDocuments, createAdlServices, type ast } from '@maa/language-adl';
import { maaGen } from './maa-gen.js';
import { ensureVenv, packageDir, repoDir, run, venvPython } from './python-env.js';

/**
 * Every method (and static attribute) of the JDK library the checker resolves
 * (language-adl's builtin-library.ts) is called from a compute block, the component is generated
 * for python-timesync and its behavior RUN in the package's venv; each result is compared with
 * what Java computes for the same statements (`java Probe.java`, skipped without a JDK).
 *
 * The setup and the cases are written in model syntax; the Java program is the same text with
 * MontiArc's constructor calls `T.T(...)` written `new T(...)`.
 */
const SETUP = `
String s = "Hello, World";
List<Integer> l = ArrayList.ArrayList();
l.add(3);
l.add(1);
l.add(3);
Map<String, Integer> m = HashMap.HashMap();
m.put("a", 1);
m.put("b", 2);
Set<String> st = HashSet.HashSet();
st.add("y");
st.add("x");
Queue<Integer> q = LinkedList.LinkedList();
q.offer(5);
q.offer(6);
Optional<String> o = Optional.of("v");
Optional<String> oe = Optional.empty();
Date d = Date.Date(86400000L);
Date d0 = Date.Date(0L);
Integer i = Integer.valueOf(42);
Long lg = Long.valueOf(-7L);
Double db = Double.valueOf(2.5);
Float fl = Float.valueOf(1.1f);
Boolean bo = Boolean.valueOf(true);
Character ch = Character.valueOf('q');
Byte by = Byte.valueOf(Byte.parseByte("5"));
Short sh = Short.valueOf(Short.parseShort("300"));
Object obj = s;
Number n = db;
Comparable<String> cs = s;
CharSequence seq = s;
Collection<Integer> col = l;
Iterable<Integer> itb = l;
Iterator<Integer> it = l.iterator();
`;

interface Case {
    /** The result's type (the out port's type). */
    readonly type: string;
    readonly expr: string;
    /** Statements before the expression (for methods without a result). */
    readonly before?: string;
}

/** Cases by library member: `Type.method(parameter types)` or `Type.ATTRIBUTE`. */
const CASES: Readonly<Record<string, readonly Case[]>> = {
    'Object.Object()': [{ type: 'boolean', expr: 'Object.Object().equals(obj)' }],
    'Object.equals(Object)': [
        { type: 'boolean', expr: 'obj.equals("Hello, World")' },
        { type: 'boolean', expr: 'i.equals(42)' },
        { type: 'boolean', expr: 'db.equals(2.5)' },
        { type: 'boolean', expr: 'l.equals(col)' },
        { type: 'boolean', expr: 'i.equals(lg)' },
    ],
    'Object.hashCode()': [
        { type: 'int', expr: 'obj.hashCode()' },
        { type: 'int', expr: 'i.hashCode()' },
        { type: 'int', expr: 'lg.hashCode()' },
        { type: 'int', expr: 'db.hashCode()' },
        { type: 'int', expr: 'fl.hashCode()' },
        { type: 'int', expr: 'bo.hashCode()' },
        { type: 'int', expr: 'ch.hashCode()' },
        { type: 'int', expr: 'l.hashCode()' },
        { type: 'int', expr: 'm.hashCode()' },
        { type: 'int', expr: 'st.hashCode()' },
        { type: 'int', expr: 'd.hashCode()' },
        { type: 'int', expr: 'o.hashCode()' },
    ],
    'Object.toString()': [
        { type: 'String', expr: 'n.toString()' },
        { type: 'String', expr: 'fl.toString()' },
        { type: 'String', expr: 'ch.toString()' },
        { type: 'String', expr: 'l.toString()' },
        { type: 'String', expr: 'm.toString()' },
        { type: 'String', expr: 'st.toString()' },
        { type: 'String', expr: 'o.toString()' },
        { type: 'String', expr: 'oe.toString()' },
        { type: 'String', expr: 'd.toString()' },
    ],
    'Comparable.compareTo(T)': [
        { type: 'int', expr: 'cs.compareTo("Help")' },
        { type: 'int', expr: 'i.compareTo(7)' },
        { type: 'int', expr: "ch.compareTo('a')" },
        { type: 'int', expr: 'd.compareTo(d0)' },
        { type: 'int', expr: 'bo.compareTo(false)' },
        { type: 'int', expr: 'db.compareTo(2.5)' },
    ],
    'CharSequence.length()': [{ type: 'int', expr: 'seq.length()' }],
    'CharSequence.charAt(int)': [{ type: 'char', expr: 'seq.charAt(1)' }],
    'CharSequence.isEmpty()': [{ type: 'boolean', expr: 'seq.isEmpty()' }],
    'Number.byteValue()': [{ type: 'byte', expr: 'Integer.valueOf(300).byteValue()' }],
    'Number.shortValue()': [{ type: 'short', expr: 'Integer.valueOf(70000).shortValue()' }],
    'Number.intValue()': [
        { type: 'int', expr: 'n.intValue()' },
        { type: 'int', expr: 'Double.valueOf(-3.9).intValue()' },
    ],
    'Number.longValue()': [{ type: 'long', expr: 'db.longValue()' }],
    'Number.floatValue()': [{ type: 'float', expr: 'n.floatValue()' }],
    'Number.doubleValue()': [{ type: 'double', expr: 'fl.doubleValue()' }],
    'Boolean.Boolean(boolean)': [{ type: 'Boolean', expr: 'Boolean.Boolean(false)' }],
    'Boolean.valueOf(boolean)': [{ type: 'Boolean', expr: 'Boolean.valueOf(true)' }],
    'Boolean.booleanValue()': [{ type: 'boolean', expr: 'bo.booleanValue()' }],
    'Boolean.toString(boolean)': [{ type: 'String', expr: 'Boolean.toString(false)' }],
    'Boolean.compare(boolean, boolean)': [{ type: 'int', expr: 'Boolean.compare(true, false)' }],
    'Boolean.parseBoolean(String)': [{ type: 'boolean', expr: 'Boolean.parseBoolean("TRUE")' }],
    'Boolean.logicalAnd(boolean, boolean)': [{ type: 'boolean', expr: 'Boolean.logicalAnd(true, false)' }],
    'Boolean.logicalOr(boolean, boolean)': [{ type: 'boolean', expr: 'Boolean.logicalOr(true, false)' }],
    'Character.Character(char)': [{ type: 'Character', expr: "Character.Character('z')" }],
    'Character.valueOf(char)': [{ type: 'Character', expr: "Character.valueOf('a')" }],
    'Character.charValue()': [{ type: 'char', expr: 'ch.charValue()' }],
    'Character.toString(char)': [{ type: 'String', expr: "Character.toString('b')" }],
    'Character.compare(char, char)': [{ type: 'int', expr: "Character.compare('a', 'd')" }],
    'Character.isDigit(char)': [
        { type: 'boolean', expr: "Character.isDigit('7')" },
        { type: 'boolean', expr: "Character.isDigit('x')" },
    ],
    'Character.isLetter(char)': [{ type: 'boolean', expr: "Character.isLetter('x')" }],
    'Character.isLetterOrDigit(char)': [{ type: 'boolean', expr: "Character.isLetterOrDigit('_')" }],
    'Character.isWhitespace(char)': [{ type: 'boolean', expr: "Character.isWhitespace(' ')" }],
    'Character.isUpperCase(char)': [{ type: 'boolean', expr: "Character.isUpperCase('Q')" }],
    'Character.isLowerCase(char)': [{ type: 'boolean', expr: "Character.isLowerCase('Q')" }],
    'Character.toUpperCase(char)': [{ type: 'char', expr: "Character.toUpperCase('q')" }],
    'Character.toLowerCase(char)': [{ type: 'char', expr: "Character.toLowerCase('Q')" }],
    'Byte.Byte(byte)': [{ type: 'Byte', expr: 'Byte.Byte(by.byteValue())' }],
    'Byte.valueOf(byte)': [{ type: 'Byte', expr: 'Byte.valueOf(Byte.MIN_VALUE)' }],
    'Byte.byteValue()': [{ type: 'byte', expr: 'by.byteValue()' }],
    'Byte.toString(byte)': [{ type: 'String', expr: 'Byte.toString(by.byteValue())' }],
    'Byte.compare(byte, byte)': [{ type: 'int', expr: 'Byte.compare(by.byteValue(), Byte.MAX_VALUE)' }],
    'Byte.MIN_VALUE': [{ type: 'byte', expr: 'Byte.MIN_VALUE' }],
    'Byte.MAX_VALUE': [{ type: 'byte', expr: 'Byte.MAX_VALUE' }],
    'Byte.parseByte(String)': [{ type: 'byte', expr: 'Byte.parseByte("-12")' }],
    'Short.Short(short)': [{ type: 'Short', expr: 'Short.Short(sh.shortValue())' }],
    'Short.valueOf(short)': [{ type: 'Short', expr: 'Short.valueOf(Short.MAX_VALUE)' }],
    'Short.shortValue()': [{ type: 'short', expr: 'sh.shortValue()' }],
    'Short.toString(short)': [{ type: 'String', expr: 'Short.toString(sh.shortValue())' }],
    'Short.compare(short, short)': [{ type: 'int', expr: 'Short.compare(sh.shortValue(), Short.MIN_VALUE)' }],
    'Short.MIN_VALUE': [{ type: 'short', expr: 'Short.MIN_VALUE' }],
    'Short.MAX_VALUE': [{ type: 'short', expr: 'Short.MAX_VALUE' }],
    'Short.parseShort(String)': [{ type: 'short', expr: 'Short.parseShort("-300")' }],
    'Integer.Integer(int)': [{ type: 'Integer', expr: 'Integer.Integer(7)' }],
    'Integer.valueOf(int)': [{ type: 'Integer', expr: 'Integer.valueOf(-3)' }],
    'Integer.intValue()': [{ type: 'int', expr: 'i.intValue()' }],
    'Integer.toString(int)': [{ type: 'String', expr: 'Integer.toString(-15)' }],
    'Integer.compare(int, int)': [{ type: 'int', expr: 'Integer.compare(3, 9)' }],
    'Integer.MIN_VALUE': [{ type: 'int', expr: 'Integer.MIN_VALUE' }],
    'Integer.MAX_VALUE': [{ type: 'int', expr: 'Integer.MAX_VALUE' }],
    'Integer.parseInt(String)': [{ type: 'int', expr: 'Integer.parseInt("-123")' }],
    'Integer.signum(int)': [{ type: 'int', expr: 'Integer.signum(-8)' }],
    'Integer.sum(int, int)': [{ type: 'int', expr: 'Integer.sum(Integer.MAX_VALUE, 1)' }],
    'Integer.max(int, int)': [{ type: 'int', expr: 'Integer.max(3, 9)' }],
    'Integer.min(int, int)': [{ type: 'int', expr: 'Integer.min(3, 9)' }],
    'Long.Long(long)': [{ type: 'Long', expr: 'Long.Long(5L)' }],
    'Long.valueOf(long)': [{ type: 'Long', expr: 'Long.valueOf(9L)' }],
    'Long.longValue()': [{ type: 'long', expr: 'lg.longValue()' }],
    'Long.toString(long)': [{ type: 'String', expr: 'Long.toString(-5L)' }],
    'Long.compare(long, long)': [{ type: 'int', expr: 'Long.compare(1L, 2L)' }],
    'Long.MIN_VALUE': [{ type: 'long', expr: 'Long.MIN_VALUE' }],
    'Long.MAX_VALUE': [{ type: 'long', expr: 'Long.MAX_VALUE' }],
    'Long.parseLong(String)': [{ type: 'long', expr: 'Long.parseLong("9000000000")' }],
    'Long.sum(long, long)': [{ type: 'long', expr: 'Long.sum(Long.MAX_VALUE, 1L)' }],
    'Float.Float(float)': [{ type: 'Float', expr: 'Float.Float(2.5f)' }],
    'Float.valueOf(float)': [{ type: 'Float', expr: 'Float.valueOf(0.1f)' }],
    'Float.floatValue()': [{ type: 'float', expr: 'fl.floatValue()' }],
    'Float.toString(float)': [{ type: 'String', expr: 'Float.toString(1.0E10f)' }],
    'Float.compare(float, float)': [{ type: 'int', expr: 'Float.compare(1.5f, 0.5f)' }],
    'Float.MIN_VALUE': [{ type: 'float', expr: 'Float.MIN_VALUE' }],
    'Float.MAX_VALUE': [{ type: 'float', expr: 'Float.MAX_VALUE' }],
    'Float.parseFloat(String)': [{ type: 'float', expr: 'Float.parseFloat("3.25")' }],
    'Float.isNaN()': [{ type: 'boolean', expr: 'fl.isNaN()' }],
    'Float.isNaN(float)': [{ type: 'boolean', expr: 'Float.isNaN(1.5f)' }],
    'Double.Double(double)': [{ type: 'Double', expr: 'Double.Double(0.5)' }],
    'Double.valueOf(double)': [{ type: 'Double', expr: 'Double.valueOf(1e-5)' }],
    'Double.doubleValue()': [{ type: 'double', expr: 'db.doubleValue()' }],
    'Double.toString(double)': [{ type: 'String', expr: 'Double.toString(123456789.0)' }],
    'Double.compare(double, double)': [{ type: 'int', expr: 'Double.compare(0.0, -0.0)' }],
    'Double.MIN_VALUE': [{ type: 'double', expr: 'Double.MIN_VALUE' }],
    'Double.MAX_VALUE': [{ type: 'double', expr: 'Double.MAX_VALUE' }],
    'Double.parseDouble(String)': [{ type: 'double', expr: 'Double.parseDouble("1e3")' }],
    'Double.isNaN()': [{ type: 'boolean', expr: 'db.isNaN()' }],
    'Double.isNaN(double)': [{ type: 'boolean', expr: 'Double.isNaN(db)' }],
    'Double.isInfinite()': [{ type: 'boolean', expr: 'db.isInfinite()' }],
    'Double.sum(double, double)': [{ type: 'double', expr: 'Double.sum(0.1, 0.2)' }],
    'String.String()': [{ type: 'String', expr: 'String.String()' }],
    'String.valueOf(Object)': [
        { type: 'String', expr: 'String.valueOf(3.5)' },
        { type: 'String', expr: 'String.valueOf(l)' },
    ],
    'String.length()': [{ type: 'int', expr: 's.length()' }],
    'String.isEmpty()': [{ type: 'boolean', expr: 's.isEmpty()' }],
    'String.charAt(int)': [{ type: 'char', expr: 's.charAt(4)' }],
    'String.substring(int)': [{ type: 'String', expr: 's.substring(7)' }],
    'String.substring(int, int)': [{ type: 'String', expr: 's.substring(0, 5)' }],
    'String.startsWith(String)': [{ type: 'boolean', expr: 's.startsWith("Hell")' }],
    'String.endsWith(String)': [{ type: 'boolean', expr: 's.endsWith("x")' }],
    'String.contains(CharSequence)': [{ type: 'boolean', expr: 's.contains("lo, W")' }],
    'String.indexOf(String)': [{ type: 'int', expr: 's.indexOf("o")' }],
    'String.lastIndexOf(String)': [{ type: 'int', expr: 's.lastIndexOf("o")' }],
    'String.equalsIgnoreCase(String)': [{ type: 'boolean', expr: 's.equalsIgnoreCase("hello, world")' }],
    'String.replace(CharSequence, CharSequence)': [{ type: 'String', expr: 's.replace("l", "L")' }],
    'String.repeat(int)': [{ type: 'String', expr: '"ab".repeat(3)' }],
    'String.toUpperCase()': [{ type: 'String', expr: 's.toUpperCase()' }],
    'String.toLowerCase()': [{ type: 'String', expr: 's.toLowerCase()' }],
    'String.trim()': [{ type: 'String', expr: '"  pad ".trim()' }],
    'String.strip()': [{ type: 'String', expr: '" x ".strip()' }],
    'String.isBlank()': [{ type: 'boolean', expr: '"   ".isBlank()' }],
    'String.concat(String)': [{ type: 'String', expr: 's.concat("!")' }],
    'Math.PI': [{ type: 'double', expr: 'Math.PI' }],
    'Math.E': [{ type: 'double', expr: 'Math.E' }],
    'Math.abs(int)': [{ type: 'int', expr: 'Math.abs(-5)' }],
    'Math.abs(long)': [{ type: 'long', expr: 'Math.abs(-5L)' }],
    'Math.abs(double)': [{ type: 'double', expr: 'Math.abs(-2.5)' }],
    'Math.sqrt(double)': [{ type: 'double', expr: 'Math.sqrt(2.0)' }],
    'Math.pow(double, double)': [{ type: 'double', expr: 'Math.pow(2.0, 10.0)' }],
    'Math.sin(double)': [{ type: 'double', expr: 'Math.sin(0.5)' }],
    'Math.cos(double)': [{ type: 'double', expr: 'Math.cos(0.5)' }],
    'Math.tan(double)': [{ type: 'double', expr: 'Math.tan(0.5)' }],
    'Math.asin(double)': [{ type: 'double', expr: 'Math.asin(0.5)' }],
    'Math.acos(double)': [{ type: 'double', expr: 'Math.acos(0.5)' }],
    'Math.atan(double)': [{ type: 'double', expr: 'Math.atan(1.0)' }],
    'Math.atan2(double, double)': [{ type: 'double', expr: 'Math.atan2(1.0, 2.0)' }],
    'Math.exp(double)': [{ type: 'double', expr: 'Math.exp(1.0)' }],
    'Math.log(double)': [{ type: 'double', expr: 'Math.log(10.0)' }],
    'Math.log10(double)': [{ type: 'double', expr: 'Math.log10(1000.0)' }],
    'Math.hypot(double, double)': [{ type: 'double', expr: 'Math.hypot(3.0, 4.0)' }],
    'Math.min(int, int)': [{ type: 'int', expr: 'Math.min(3, -4)' }],
    'Math.max(int, int)': [{ type: 'int', expr: 'Math.max(3, -4)' }],
    'Math.min(long, long)': [{ type: 'long', expr: 'Math.min(3L, 9L)' }],
    'Math.max(long, long)': [{ type: 'long', expr: 'Math.max(3L, 9L)' }],
    'Math.min(double, double)': [{ type: 'double', expr: 'Math.min(-0.0, 0.0)' }],
    'Math.max(double, double)': [{ type: 'double', expr: 'Math.max(1.5, 2.5)' }],
    'Math.signum(double)': [{ type: 'double', expr: 'Math.signum(-3.2)' }],
    'Math.floor(double)': [{ type: 'double', expr: 'Math.floor(-1.5)' }],
    'Math.ceil(double)': [{ type: 'double', expr: 'Math.ceil(-1.5)' }],
    'Math.round(double)': [
        { type: 'long', expr: 'Math.round(2.5)' },
        { type: 'long', expr: 'Math.round(-2.5)' },
    ],
    'Math.toRadians(double)': [{ type: 'double', expr: 'Math.toRadians(180.0)' }],
    'Math.toDegrees(double)': [{ type: 'double', expr: 'Math.toDegrees(1.0)' }],
    'Iterator.hasNext()': [{ type: 'boolean', expr: 'it.hasNext()' }],
    'Iterator.next()': [{ type: 'Integer', expr: 'it.next()' }],
    'Iterable.iterator()': [{ type: 'Integer', expr: 'itb.iterator().next()' }],
    'Collection.size()': [
        { type: 'int', expr: 'col.size()' },
        { type: 'int', expr: 'st.size()' },
    ],
    'Collection.isEmpty()': [{ type: 'boolean', expr: 'col.isEmpty()' }],
    'Collection.contains(Object)': [
        { type: 'boolean', expr: 'col.contains(1)' },
        { type: 'boolean', expr: 'st.contains("x")' },
    ],
    'Collection.add(E)': [
        { type: 'boolean', expr: 'col.add(4)' },
        { type: 'boolean', expr: 'st.add("x")' },
    ],
    'Collection.remove(Object)': [
        { type: 'boolean', expr: 'col.remove(Integer.valueOf(3))' },
        { type: 'boolean', expr: 'st.remove("z")' },
    ],
    'Collection.clear()': [
        { type: 'int', before: 'Set<String> cleared = HashSet.HashSet(); cleared.add("a"); cleared.clear();', expr: 'cleared.size()' },
    ],
    'List.get(int)': [{ type: 'Integer', expr: 'l.get(0)' }],
    'List.set(int, E)': [{ type: 'Integer', expr: 'l.set(1, 8)' }],
    'List.indexOf(Object)': [{ type: 'int', expr: 'l.indexOf(3)' }],
    'List.lastIndexOf(Object)': [{ type: 'int', expr: 'l.lastIndexOf(8)' }],
    'Queue.peek()': [{ type: 'Integer', expr: 'q.peek()' }],
    'Queue.poll()': [{ type: 'Integer', expr: 'q.poll()' }],
    'Queue.offer(E)': [{ type: 'boolean', expr: 'q.offer(7)' }],
    'Map.get(Object)': [{ type: 'Integer', expr: 'm.get("a")' }],
    'Map.put(K, V)': [{ type: 'Integer', expr: 'm.put("a", 5)' }],
    'Map.containsKey(Object)': [
        { type: 'boolean', expr: 'm.containsKey("b")' },
        { type: 'boolean', expr: 'm.containsKey("z")' },
    ],
    'Map.containsValue(Object)': [{ type: 'boolean', expr: 'm.containsValue(2)' }],
    'Map.remove(Object)': [{ type: 'Integer', expr: 'm.remove("b")' }],
    'Map.getOrDefault(Object, V)': [{ type: 'Integer', expr: 'm.getOrDefault("z", 0)' }],
    'Map.size()': [{ type: 'int', expr: 'm.size()' }],
    'Map.isEmpty()': [{ type: 'boolean', expr: 'm.isEmpty()' }],
    'Map.clear()': [
        {
            type: 'boolean',
            before: 'Map<String, Integer> gone = HashMap.HashMap(); gone.put("k", 1); gone.clear();',
            expr: 'gone.isEmpty()',
        },
    ],
    'Map.keySet()': [{ type: 'Set<String>', before: 'm.put("c", 3);', expr: 'm.keySet()' }],
    'Map.values()': [{ type: 'Collection<Integer>', expr: 'm.values()' }],
    'ArrayList.ArrayList()': [{ type: 'int', expr: 'ArrayList.ArrayList().size()' }],
    'LinkedList.LinkedList()': [{ type: 'boolean', expr: 'LinkedList.LinkedList().isEmpty()' }],
    'HashSet.HashSet()': [{ type: 'int', expr: 'HashSet.HashSet().size()' }],
    'HashMap.HashMap()': [{ type: 'boolean', expr: 'HashMap.HashMap().isEmpty()' }],
    'Optional.empty()': [{ type: 'Optional<String>', expr: 'Optional.empty()' }],
    'Optional.of(T)': [{ type: 'Optional<String>', expr: 'Optional.of("w")' }],
    'Optional.ofNullable(T)': [{ type: 'Optional<String>', expr: 'Optional.ofNullable(null)' }],
    'Optional.isPresent()': [
        { type: 'boolean', expr: 'o.isPresent()' },
        { type: 'boolean', expr: 'oe.isPresent()' },
    ],
    'Optional.isEmpty()': [{ type: 'boolean', expr: 'oe.isEmpty()' }],
    'Optional.get()': [{ type: 'String', expr: 'o.get()' }],
    'Optional.orElse(T)': [{ type: 'String', expr: 'oe.orElse("w")' }],
    'Date.Date()': [{ type: 'boolean', expr: 'Date.Date().after(d0)' }],
    'Date.Date(long)': [{ type: 'Date', expr: 'Date.Date(1000L)' }],
    'Date.getTime()': [{ type: 'long', expr: 'd.getTime()' }],
    'Date.setTime(long)': [{ type: 'long', before: 'd.setTime(5000L);', expr: 'd.getTime()' }],
    'Date.before(Date)': [{ type: 'boolean', expr: 'd.before(d0)' }],
    'Date.after(Date)': [{ type: 'boolean', expr: 'd.after(d0)' }],
    'Collections.emptyList()': [{ type: 'int', expr: 'Collections.emptyList().size()' }],
    'Collections.emptySet()': [{ type: 'boolean', expr: 'Collections.emptySet().isEmpty()' }],
    'Collections.emptyMap()': [{ type: 'int', expr: 'Collections.emptyMap().size()' }],
    'Collections.singletonList(T)': [{ type: 'List<Integer>', expr: 'Collections.singletonList(4)' }],
};

/** The members of the built-in library as `Type.method(parameter types)` / `Type.ATTRIBUTE`. */
function libraryMembers(): string[] {
    const services = createAdlServices(EmptyFileSystem);
    const keys: string[] = [];
    for (const doc of builtinDocuments(services.shared)) {
        const model = doc.parseResult.value as ast.CDModel;
        expect(doc.parseResult.parserErrors, doc.uri.toString()).toEqual([]);
        for (const t of model.diagram.elements) {
            if (t.$type !== 'CDClass') continue;
            for (const m of t.members) {
                if (m.$type === 'CDAttribute') keys.push(`${t.name}.${m.name}`);
                else keys.push(`${t.name}.${m.name}(${m.params.map((p) => p.type.$cstNode?.text ?? '?').join(', ')})`);
            }
        }
    }
    return keys;
}

const cases = Object.entries(CASES).flatMap(([key, cs]) => cs.map((c) => ({ key, ...c })));

/** Model syntax to Java: MontiArc's `T.T(...)` constructor calls become `new T(...)`. */
function toJava(text: string): string {
    return text.replace(/\b([A-Z]\w*)\.\1\(/g, 'new $1(');
}

/** The result types a ROS 2 port can carry (std_msgs); the ROS 2 probe has the cases of these types. */
const ROS_TYPES = new Set(['boolean', 'byte', 'short', 'int', 'long', 'float', 'double', 'char', 'String']);
const rosCases = cases.map((c, k) => ({ ...c, k })).filter((c) => ROS_TYPES.has(c.type));

/**
 * A component computing every case in its compute block, in order (cases change the sample
 * collections, later ones see the changes); the `selected` ones go to an out port `r<index>`,
 * the others are evaluated as statements.
 */
function arcModel(name: string, selected: ReadonlyArray<Case & { k: number }>): string {
    const out = new Set(selected.map((c) => c.k));
    const ports = selected.map((c) => `  port <<sync>> out ${c.type} r${c.k};`).join('\n');
    const body = cases.map((c, k) => `${c.before ?? ''}\n    ${out.has(k) ? `r${k} = ` : ''}${c.expr};`).join('\n');
    return `package probe;\n\nimport java.util.*;\n\ncomponent ${name} {\n  port <<sync>> in int tick;\n${ports}\n\n  compute {\n${SETUP.split(
        '\n',
    )
        .map((x) => `    ${x}`)
        .join('\n')}\n    ${body}\n  }\n}\n`;
}

function javaProgram(): string {
    const body = cases
        .map(
            (c, k) => `${toJava(c.before ?? '')}\n    ${c.type} r${k} = ${toJava(c.expr)};\n    System.out.println(String.valueOf(r${k}));`,
        )
        .join('\n');
    return `import java.util.*;\n\n@SuppressWarnings({"unchecked", "rawtypes", "deprecation", "removal"})\npublic class Probe {\n  public static void main(String[] args) {\n${toJava(SETUP)}\n${body}\n  }\n}\n`;
}

// Runs one step of a generated behavior class and prints each out port r<k> as Java's String.valueOf would.
const PY_HARNESS = `
import importlib, json, sys
sys.path.insert(0, sys.argv[1])
behavior = getattr(importlib.import_module(sys.argv[2]), sys.argv[3])
from maa_behavior import jformat
wanted = json.loads(sys.argv[4])
out = {}
b = behavior(lambda port, value: out.__setitem__(port, value))
b.init()
b.step({"tick": 1})
for k, t in wanted:
    port = f"r{k}"
    print(jformat(out[port], t) if port in out else "<nothing emitted>")
`;

describe('the JDK library in generated Python', () => {
    it('every library member has a case whose expression calls it', () => {
        const members = libraryMembers();
        expect(members.length).toBeGreaterThan(150);
        const missing = members.filter((k) => !CASES[k]);
        expect(missing).toEqual([]);
        const stale = Object.keys(CASES).filter((k) => !members.includes(k));
        expect(stale).toEqual([]);
        for (const [key, cs] of Object.entries(CASES)) {
            const name = key.replace(/^\w+\./, '').replace(/\(.*$/, '');
            for (const c of cs) expect(`${c.before ?? ''} ${c.expr}`, key).toMatch(new RegExp(`\\b${name}\\b`));
        }
    });

    const work = mkdtempSync(path.join(tmpdir(), 'maa-java-library-'));
    afterAll(() => rmSync(work, { recursive: true, force: true }));
    let python: string[] = [];
    let ros: string[] = [];
    let javaLines: string[] | undefined;

    beforeAll(async () => {
        await ensureVenv();
        const root = path.join(work, 'models');
        mkdirSync(path.join(root, 'probe'), { recursive: true });
        writeFileSync(
            path.join(root, 'probe', 'LibProbe.arc'),
            arcModel(
                'LibProbe',
                cases.map((c, k) => ({ ...c, k })),
            ),
        );
        writeFileSync(path.join(root, 'probe', 'RosProbe.arc'), arcModel('RosProbe', rosCases));
        writeFileSync(
            path.join(root, 'Probe.arcapp'),
            'application Probe for probe.LibProbe {\n  platform timesync {\n    timesync.Components;\n    timesync.DataTypes;\n  }\n}\n',
        );
        writeFileSync(
            path.join(root, 'RosProbe.arcapp'),
            'application RosProbe for probe.RosProbe {\n  platform rospython {\n    ros2.Components;\n    ros2.DataTypes;\n  }\n}\n',
        );
        const out = path.join(work, 'out');
        const generate = async (app: string, platform: string): Promise<void> => {
            const gen = await run(
                process.execPath,
                [maaGen, 'generate', path.join(root, app), '--platform', platform, '--out', out],
                repoDir,
            );
            if (gen.status !== 0) throw new Error(`maa-gen generate ${app} failed:\n${gen.stdout}\n${gen.stderr}`);
        };
        const runBehavior = async (
            dir: string,
            module: string,
            cls: string,
            wanted: ReadonlyArray<readonly [number, string]>,
        ): Promise<string[]> => {
            const py = await run(venvPython, ['-c', PY_HARNESS, dir, module, cls, JSON.stringify(wanted)], packageDir);
            if (py.status !== 0) throw new Error(`the generated code failed:\n${py.stdout}\n${py.stderr}`);
            return py.stdout.trimEnd().split('\n');
        };
        await generate('Probe.arcapp', 'timesync');
        python = await runBehavior(
            path.join(out, 'timesync'),
            'probe.lib_probe',
            'LibProbeBehavior',
            cases.map((c, k) => [k, c.type] as const),
        );
        // The ROS 2 build's behavior module is plain Python (no rclpy): run it the same way.
        await generate('RosProbe.arcapp', 'rospython');
        ros = await runBehavior(
            path.join(out, 'rospython', 'ros_probe'),
            'ros_probe.model.probe.ros_probe_behavior',
            'RosProbeBehavior',
            rosCases.map((c) => [c.k, c.type] as const),
        );
        const javaDir = path.join(work, 'java');
        mkdirSync(javaDir);
        writeFileSync(path.join(javaDir, 'Probe.java'), javaProgram());
        const java = await run('java', ['-Duser.timezone=UTC', '-Duser.language=en', 'Probe.java'], javaDir);
        if (java.status === 0) javaLines = java.stdout.trimEnd().split('\n');
        else if (!/ENOENT|not found/i.test(java.stderr)) throw new Error(`java Probe.java failed:\n${java.stderr}`);
    }, 300_000);

    it('the generated calls give what Java gives', (ctx) => {
        if (!javaLines) {
            ctx.skip();
            return;
        }
        expect(python).toHaveLength(cases.length);
        const rows = cases.map((c, k) => `${c.key}: ${c.expr} = ${python[k]}`);
        const expected = cases.map((c, k) => `${c.key}: ${c.expr} = ${javaLines![k]}`);
        expect(rows).toEqual(expected);
    });

    it('the ROS 2 build computes the same (cases with results a ROS 2 port carries)', (ctx) => {
        if (!javaLines) {
            ctx.skip();
            return;
        }
        expect(rosCases.length).toBeGreaterThan(150);
        const rows = rosCases.map((c, i) => `${c.key}: ${c.expr} = ${ros[i]}`);
        const expected = rosCases.map((c) => `${c.key}: ${c.expr} = ${javaLines![c.k]}`);
        expect(rows).toEqual(expected);
    });
});
