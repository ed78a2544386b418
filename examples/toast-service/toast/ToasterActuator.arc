package toast;

import toast.types.*;

/* Pushes or releases the toaster lever (platform component). */
<<handwritten>> component ToasterActuator {
  port in ToasterCmd cmd;
}
