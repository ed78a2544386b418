import { ADL_DIAGNOSTICS } from '../src/index.js';
import { describeCatalog } from '../src/testing/index.js';
import { validate } from './helpers.js';

describeCatalog(ADL_DIAGNOSTICS, validate);
