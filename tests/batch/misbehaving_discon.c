/* A DISCON library that misbehaves on demand, for the batch's isolation of
 * cases (batch_test.cpp). The first word of its input file (accINFILE) says
 * how: "hold T" demands zero pitch and a generator torque of T N*m at every
 * step (a well-behaved controller), "segv" writes through a null pointer,
 * "loop" never returns, "nan" demands a NaN pitch, "exit" calls exit(3). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EXPORT __attribute__((visibility("default")))

EXPORT void DISCON(float* avrSWAP, int* aviFAIL, const char* accINFILE, char* avcOUTNAME,
                   char* avcMSG);

void DISCON(float* avrSWAP, int* aviFAIL, const char* accINFILE, char* avcOUTNAME, char* avcMSG) {
    (void)avcOUTNAME;
    (void)avcMSG;
    char mode[16] = "";
    double torque = 0;
    FILE* in = fopen(accINFILE, "r");
    if (!in || fscanf(in, "%15s %lf", mode, &torque) < 1) {
        if (in) fclose(in);
        *aviFAIL = -1;
        return;
    }
    fclose(in);
    const double time = avrSWAP[1];
    if (time > 0.5) {
        if (strcmp(mode, "segv") == 0) {
            volatile int* nowhere = NULL;
            *nowhere = 1;
        } else if (strcmp(mode, "loop") == 0) {
            for (volatile unsigned long i = 0;; ++i) {
            }
        } else if (strcmp(mode, "exit") == 0) {
            exit(3);
        }
    }
    const float pitch = strcmp(mode, "nan") == 0 && time > 0.5 ? strtof("nan", NULL) : 0.0f;
    for (int i = 41; i <= 44; ++i) avrSWAP[i] = pitch;
    avrSWAP[34] = 1.0f;
    avrSWAP[35] = 0.0f;
    avrSWAP[45] = 0.0f;
    avrSWAP[46] = (float)torque;
    avrSWAP[47] = 0.0f;
    avrSWAP[54] = 0.0f;
    avrSWAP[55] = 0.0f;
    avrSWAP[64] = 0.0f;
    *aviFAIL = 0;
}
