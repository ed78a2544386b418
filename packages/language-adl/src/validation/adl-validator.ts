import type { AdlServices } from '../adl-module.js';
import { AutoConnectChecks } from './checks/autoconnect-checks.js';
import { ConnectorChecks } from './checks/connector-checks.js';
import { ExpressionChecks } from './checks/expression-checks.js';
import { InstantiationChecks } from './checks/instantiation-checks.js';
import { StatementChecks } from './checks/statement-checks.js';
import { StructureChecks } from './checks/structure-checks.js';
import { VariabilityChecks } from './checks/variability-checks.js';

/** Registers the context conditions of the host language (ARCHITECTURE.md section 5, `arc/*`, `expr/*`). */
export function registerAdlChecks(services: AdlServices): void {
    const registry = services.validation.ValidationRegistry;
    // A variable component's structure and connectors are checked in each of its configurations.
    const variability = new VariabilityChecks(services);
    registry.register(variability.perVariant(new StructureChecks(services).checks));
    registry.register(variability.perVariant(new ConnectorChecks(services).checks));
    registry.register(new InstantiationChecks(services).checks);
    const expressions = new ExpressionChecks(services);
    registry.register(expressions.checks);
    registry.register(new AutoConnectChecks().checks);
    registry.register(new StatementChecks(services, expressions).checks);
    registry.register(variability.checks);
}
