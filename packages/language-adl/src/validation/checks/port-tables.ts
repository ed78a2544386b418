import type { AstNode } from 'langium';
import type { PortInfo } from '../../components/component-model.js';

/**
 * The ports of components and subcomponents by name, computed once per check run: looking up
 * each connector end with findPort listed all ports again, which made the connector checks
 * quadratic in the number of ports (1,000 connectors took seconds, 5,000 minutes).
 * Create one per check run: the tables must not outlive the model they were computed from.
 */
export class PortTables {
    private readonly tables = new Map<AstNode, ReadonlyMap<string, PortInfo>>();

    /** The port `name` among the ports of `owner` (a component or a subcomponent), the first of that name. */
    port(owner: AstNode, name: string, ports: () => readonly PortInfo[]): PortInfo | undefined {
        let table = this.tables.get(owner);
        if (!table) {
            const m = new Map<string, PortInfo>();
            for (const p of ports()) if (!m.has(p.name)) m.set(p.name, p);
            this.tables.set(owner, m);
            table = m;
        }
        return table.get(name);
    }
}
