import { Cancellation, interruptAndCheck, isAstNode, isMultiReference, isReference, type AstNode, type ReferenceInfo } from 'langium';

/**
 * The AST walks of the checker's per-document phases (linking, indexing references, validating),
 * in exactly the order of Langium's `AstUtils.streamAst` and `streamReferences` but without their
 * streams: those cost an iterator object, a keys array and closures per node, and the three walks
 * took about 15 % of a cold `maa-gen check` of the benchmark model (docs/performance.md).
 */

/** Pushes a node's child nodes onto a stack so that they pop in property order (as streamAst yields them). */
export function pushChildren(node: AstNode, stack: AstNode[]): void {
    const start = stack.length;
    for (const key of Object.keys(node)) {
        if (key.charCodeAt(0) === 36 /* '$' */) continue;
        const value: unknown = (node as unknown as Record<string, unknown>)[key];
        if (Array.isArray(value)) {
            for (const element of value) if (isAstNode(element)) stack.push(element);
        } else if (isAstNode(value)) {
            stack.push(value);
        }
    }
    // Pushed in order; reversed so that the first child is popped first.
    for (let i = start, j = stack.length - 1; i < j; i++, j--) {
        const t = stack[i]!;
        stack[i] = stack[j]!;
        stack[j] = t;
    }
}

/** Calls `visit` on every reference of a node, as `AstUtils.streamReferences` yields them. */
export function forEachReference(node: AstNode, visit: (ref: ReferenceInfo) => void): void {
    for (const property of Object.keys(node)) {
        if (property.charCodeAt(0) === 36 /* '$' */) continue;
        const value: unknown = (node as unknown as Record<string, unknown>)[property];
        if (isReference(value) || isMultiReference(value)) {
            visit({ reference: value, container: node, property });
        } else if (Array.isArray(value)) {
            // Langium yields the elements of an array that are single references.
            for (let index = 0; index < value.length; index++) {
                const element: unknown = value[index];
                if (isReference(element)) visit({ reference: element, container: node, property, index });
            }
        }
    }
}

/**
 * Lets other work run and honours a cancellation, as Langium does between two nodes: the promise
 * to await, or undefined without a token (the CLI's checks), where there is nothing to wait for,
 * so that no promise is made and awaited per node.
 */
export function betweenNodes(token: Cancellation.CancellationToken): Promise<void> | undefined {
    return token === Cancellation.CancellationToken.None ? undefined : interruptAndCheck(token);
}

/** Calls `visit` on every reference below and including `root`, in Langium's order, between nodes as Langium does. */
export async function forEachReferenceBelow(
    root: AstNode,
    cancelToken: Cancellation.CancellationToken,
    visit: (ref: ReferenceInfo) => void,
): Promise<void> {
    const stack: AstNode[] = [root];
    while (stack.length > 0) {
        const wait = betweenNodes(cancelToken);
        if (wait) await wait;
        const node = stack.pop()!;
        forEachReference(node, visit);
        pushChildren(node, stack);
    }
}

/** Every node of a tree, pre-order, as `AstUtils.streamAst(root).toArray()`. */
export function astNodesOf(root: AstNode): AstNode[] {
    const out: AstNode[] = [];
    const stack: AstNode[] = [root];
    while (stack.length > 0) {
        const node = stack.pop()!;
        out.push(node);
        pushChildren(node, stack);
    }
    return out;
}
