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
    ['Double', 'double', true],
];

/** Static members of a box beyond those every box has (MIN/MAX values, parsing, character classes). */
const BOX_EXTRAS: Readonly<Record<string, string>> = {
    Boolean:
        ' static boolean parseBoolean(String s); static boolean logicalAnd(boolean a, boolean b); static boolean logicalOr(boolean a, boolean b);',
    Character:
        ' static boolean isDigit(char c); static boolean isLetter(char c); static boolean isLetterOrDigit(char c); static boolean isWhitespace(char c);' +
        ' static boolean isUpperCase(char c); static boolean isLowerCase(char c); static char toUpperCase(char c); static char toLowerCase(char c);',
    Byte: ' static byte MIN_VALUE; static byte MAX_VALUE; static byte parseByte(String s);',
    Short: ' static short MIN_VALUE; static short MAX_VALUE; static short parseShort(String s);',
    Integer:
        ' static int MIN_VALUE; static int MAX_VALUE; static int parseInt(String s); static int signum(int i); static int sum(int a, int b);' +
        ' static int max(int a, int b); static int min(int a, int b);',
    Long: ' static long MIN_VALUE; static long MAX_VALUE; static long parseLong(String s); static long sum(long a, long b);',
    Float: ' static float MIN_VALUE; static float MAX_VALUE; static float parseFloat(String s); boolean isNaN(); static boolean isNaN(float v);',
    Double:
        ' static double MIN_VALUE; static double MAX_VALUE; static double parseDouble(String s); boolean isNaN(); static boolean isNaN(double v);' +
        ' boolean isInfinite(); static double sum(double a, double b);',
};

const javaLang = `package java.lang;
classdiagram Lang {
  class Object { static Object Object(); boolean equals(Object other); int hashCode(); String toString(); }
  interface Comparable<T> { int compareTo(T other); }
  interface CharSequence { int length(); char charAt(int index); boolean isEmpty(); }
  abstract class Number {
    byte byteValue(); short shortValue(); int intValue(); long longValue(); float floatValue(); double doubleValue();
  }
${boxes
    .map(
        ([box, prim, numeric]) =>
            `  class ${box} ${numeric ? 'extends Number ' : ''}implements Comparable<${box}> { static ${box} ${box}(${prim} value); static ${box} valueOf(${prim} value); ${prim} ${prim}Value(); static String toString(${prim} value); static int compare(${prim} a, ${prim} b);${BOX_EXTRAS[box] ?? ''} }`,
    )
    .join('\n')}
  class String implements Comparable<String>, CharSequence {
    static String String(); static String valueOf(Object value);
    int length(); boolean isEmpty(); char charAt(int index); String substring(int begin); String substring(int begin, int end);
    boolean startsWith(String prefix); boolean endsWith(String suffix); boolean contains(CharSequence s);
    int indexOf(String s); int lastIndexOf(String s); boolean equalsIgnoreCase(String other);
    String replace(CharSequence target, CharSequence replacement); String repeat(int count);
    String toUpperCase(); String toLowerCase(); String trim(); String strip(); boolean isBlank(); String concat(String other);
  }
  class Math {
    static double PI; static double E;
    static int abs(int a); static long abs(long a); static double abs(double a); static double sqrt(double a); static double pow(double a, double b);
    static double sin(double a); static double cos(double a); static double tan(double a); static double asin(double a); static double acos(double a); static double atan(double a);
    static double atan2(double y, double x); static double exp(double a); static double log(double a); static double log10(double a); static double hypot(double x, double y);
    static int min(int a, int b); static int max(int a, int b); static long min(long a, long b); static long max(long a, long b);
    static double min(double a, double b); static double max(double a, double b); static double signum(double d);
    static double floor(double a); static double ceil(double a); static long round(double a);
    static double toRadians(double deg); static double toDegrees(double rad);
  }
}
`;

const javaUtil = `package java.util;
classdiagram Util {
  interface Iterator<E> { boolean hasNext(); E next(); }
  interface Iterable<T> { Iterator<T> iterator(); }
  interface Collection<E> extends Iterable<E> {
    int size(); boolean isEmpty(); boolean contains(Object o); boolean add(E e); boolean remove(Object o); void clear();
  }
  interface List<E> extends Collection<E> { E get(int index); E set(int index, E element); int indexOf(Object o); int lastIndexOf(Object o); }
  interface Set<E> extends Collection<E>;
  interface Queue<E> extends Collection<E> { E peek(); E poll(); boolean offer(E e); }
  interface Deque<E> extends Queue<E>;
  interface Map<K, V> {
    V get(Object key); V put(K key, V value); boolean containsKey(Object key); boolean containsValue(Object value);
    V remove(Object key); V getOrDefault(Object key, V defaultValue); int size(); boolean isEmpty(); void clear();
    Set<K> keySet(); Collection<V> values();
  }
  class ArrayList<E> implements List<E> { static <E> ArrayList<E> ArrayList(); }
  class LinkedList<E> implements List<E>, Deque<E> { static <E> LinkedList<E> LinkedList(); }
  class HashSet<E> implements Set<E> { static <E> HashSet<E> HashSet(); }
  class HashMap<K, V> implements Map<K, V> { static <K, V> HashMap<K, V> HashMap(); }
  class Optional<T> {
    static <T> Optional<T> empty(); static <T> Optional<T> of(T value); static <T> Optional<T> ofNullable(T value);
    boolean isPresent(); boolean isEmpty(); T get(); T orElse(T other);
  }
  class Date implements Comparable<Date> {
    static Date Date(); static Date Date(long time);
    long getTime(); void setTime(long time); boolean before(Date when); boolean after(Date when);
  }
  class Collections {
    static <T> List<T> emptyList(); static <T> Set<T> emptySet(); static <K, V> Map<K, V> emptyMap();
    static <T> List<T> singletonList(T o);
  }
}
`;

export const BUILTIN_DOCUMENTS: readonly BuiltinDocument[] = [
    { uri: 'builtin:/java/lang/Lang.cd', text: javaLang },
    { uri: 'builtin:/java/util/Util.cd', text: javaUtil },
];

/** Boxed class name for each primitive, and back. */
export const BOX_OF: ReadonlyMap<string, string> = new Map(boxes.map(([box, prim]) => [prim, box]));
export const UNBOX_OF: ReadonlyMap<string, string> = new Map(boxes.map(([box, prim]) => [box, prim]));
