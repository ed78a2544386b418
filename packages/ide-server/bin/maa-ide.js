#!/usr/bin/env node
// Thin launcher so that the bin exists before the first build (npm links bins at install time).
import { run } from '../dist/cli.js';

run(process.argv);
