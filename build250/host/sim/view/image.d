build250/host/sim/view/image.o: sim/view/image.c sim/view/image.h \
 /usr/include/libpng16/png.h /usr/include/libpng16/pnglibconf.h \
 /usr/include/libpng16/pngconf.h sim/view/font.h sim/io/outfile.h
sim/view/image.h:
/usr/include/libpng16/png.h:
/usr/include/libpng16/pnglibconf.h:
/usr/include/libpng16/pngconf.h:
sim/view/font.h:
sim/io/outfile.h:
