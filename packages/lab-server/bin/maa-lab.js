#!/usr/bin/env node
// Thin launcher so that the bin exists before the first build (npm links bins at install time).
import { runLab } from '../dist/cli/main.js';

const code = await runLab(process.argv);
// serve keeps running (its server holds the event loop); every other command ends here.
if (code !== 0) process.exitCode = code;
