import type { ValidationAcceptor, ValidationChecks } from 'langium';
import type { AdlAstType, BehaviorDeclaration, ComponentType } from '../../generated/ast.js';
import { autoConnectsOf } from '../../components/autoconnect.js';
import { behaviorsOf, isComposed } from '../../components/component-model.js';
import { Codes } from '../codes.js';

/**
 * Context conditions of MontiArc's `autoconnect` (at most one per component, none in atomic
 * components: MontiArc's MaxOneAutoConnect and AtomicNoAutoConnect) and of behaviors in
 * decomposed components (a decomposed component's behavior is that of its subcomponents, so a
 * behavior declared beside them would never run).
 */
export class AutoConnectChecks {
    readonly checks: ValidationChecks<AdlAstType> = {
        ComponentType: (c, accept) => {
            this.checkAutoConnects(c, accept);
            this.checkBehaviorInDecomposed(c, accept);
        },
    };

    private checkAutoConnects(c: ComponentType, accept: ValidationAcceptor): void {
        const decls = autoConnectsOf(c);
        if (decls.length === 0) return;
        if (!isComposed(c)) {
            for (const d of decls) {
                accept(
                    'error',
                    `Component '${c.name}' has no subcomponents, so 'autoconnect ${d.kind};' has nothing to connect; autoconnect is only allowed in decomposed components.`,
                    { node: d, code: Codes.AutoConnectInAtomic },
                );
            }
        }
        for (const d of decls.slice(1)) {
            accept(
                'error',
                `Component '${c.name}' declares more than one autoconnect ('autoconnect ${decls.map((x) => x.kind).join(";', 'autoconnect ")};'); at most one is allowed.`,
                { node: d, code: Codes.MultipleAutoConnects },
            );
        }
    }

    private checkBehaviorInDecomposed(c: ComponentType, accept: ValidationAcceptor): void {
        if (!isComposed(c)) return;
        for (const b of behaviorsOf(c)) {
            if (!isComputingBehavior(b)) continue;
            const keyword = behaviorKeyword(b);
            accept(
                'error',
                `Component '${c.name}' has subcomponents and declares a behavior ('${keyword}'); the behavior of a decomposed component is that of its subcomponents and connectors, so this ${keyword} would never run. Move it into an atomic subcomponent or remove the subcomponents.`,
                { node: b, code: Codes.BehaviorInDecomposed },
            );
        }
    }
}

/**
 * Whether a behavior computes the component's outputs: not an `init` block (it only initializes
 * fields) and not a mode automaton (which belongs to decomposed components).
 */
function isComputingBehavior(b: BehaviorDeclaration): boolean {
    const type = b.behavior?.$type;
    return type !== undefined && type !== 'InitBlock' && !type.startsWith('Mode');
}

function behaviorKeyword(b: BehaviorDeclaration): string {
    const text = b.behavior?.$cstNode?.text ?? '';
    return /^[A-Za-z_]\w*/.exec(text)?.[0] ?? b.behavior?.$type ?? 'behavior';
}
