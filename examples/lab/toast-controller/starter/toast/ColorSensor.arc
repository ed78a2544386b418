package toast;

import toast.types.*;

/* Browning of the toast, classified by the color sensor above the toaster slot (platform component). */
<<handwritten>> component ColorSensor {
  port <<sync>> out ToastColor value;
}
