/**
 * The `java.lang` and `java.util` types that MontiArc models use, written as class diagrams and
 * loaded into every model root (URI scheme `builtin:`). Constructors are written the MontiArc
 * way, as a static method named like the class (`java.lang.String.String()`).
 */
export interface BuiltinDocument {
    readonly uri: string;
    readonly text: string;
}

const boxes: ReadonlyArray<readonly [string, string, boolean]> = [
    ['Boolean', 'boolean', false],
    ['Character', 'char', false],
    ['Byte', 'byte', true],
    ['Short', 'short', true],
    ['Integer', 'int', true],
    ['Long', 'long', true],
    ['Float', 'float', true],
    ['Double', 'double', true]
];

const javaLang = `package java.lang;
classdiagram Lang {
  class Object { static Object Object(); boolean equals(Object other); int hashCode(); String toString(); }
  interface Comparable<T> { int compareTo(T other); }
  interface CharSequence { int length(); }
  abstract class Number { int intValue(); long longValue(); float floatValue(); double doubleValue(); }
${boxes.map(([box, prim, numeric]) =>
    `  class ${box} ${numeric ? 'extends Number ' : ''}implements Comparable<${box}> { static ${box} ${box}(${prim} value); static ${box} valueOf(${prim} value); ${prim} ${prim}Value(); }`).join('\n')}
  class String implements Comparable<String>, CharSequence {
    static String String(); static String valueOf(Object value);
    int length(); boolean isEmpty(); char charAt(int index); String substring(int begin, int end);
    boolean startsWith(String prefix); boolean endsWith(String suffix); boolean contains(CharSequence s);
    String toUpperCase(); String toLowerCase(); String trim(); String concat(String other);
  }
  class Math {
    static int abs(int a); static long abs(long a); static double abs(double a); static double sqrt(double a); static double pow(double a, double b);
    static double sin(double a); static double cos(double a); static double tan(double a);
    static double atan2(double y, double x); static int min(int a, int b); static int max(int a, int b);
    static double min(double a, double b); static double max(double a, double b);
    static double floor(double a); static double ceil(double a); static long round(double a);
    static double toRadians(double deg); static double toDegrees(double rad);
  }
}
`;

const javaUtil = `package java.util;
classdiagram Util {
  interface Iterable<T>;
  interface Collection<E> extends Iterable<E> { int size(); boolean isEmpty(); boolean contains(Object o); boolean add(E e); }
  interface List<E> extends Collection<E> { E get(int index); E set(int index, E element); }
  interface Set<E> extends Collection<E>;
  interface Queue<E> extends Collection<E> { E peek(); E poll(); boolean offer(E e); }
  interface Deque<E> extends Queue<E>;
  interface Map<K, V> { V get(Object key); V put(K key, V value); boolean containsKey(Object key); int size(); }
  class ArrayList<E> implements List<E> { static <E> ArrayList<E> ArrayList(); }
  class LinkedList<E> implements List<E>, Deque<E> { static <E> LinkedList<E> LinkedList(); }
  class HashSet<E> implements Set<E> { static <E> HashSet<E> HashSet(); }
  class HashMap<K, V> implements Map<K, V> { static <K, V> HashMap<K, V> HashMap(); }
  class Optional<T> { static <T> Optional<T> empty(); static <T> Optional<T> of(T value); boolean isPresent(); T get(); }
  class Collections {
    static <T> List<T> emptyList(); static <T> Set<T> emptySet(); static <K, V> Map<K, V> emptyMap();
    static <T> List<T> singletonList(T o);
  }
}
`;

export const BUILTIN_DOCUMENTS: readonly BuiltinDocument[] = [
    { uri: 'builtin:/java/lang/Lang.cd', text: javaLang },
    { uri: 'builtin:/java/util/Util.cd', text: javaUtil }
];

/** Boxed class name for each primitive, and back. */
export const BOX_OF: ReadonlyMap<string, string> = new Map(boxes.map(([box, prim]) => [prim, box]));
export const UNBOX_OF: ReadonlyMap<string, string> = new Map(boxes.map(([box, prim]) => [box, prim]));
