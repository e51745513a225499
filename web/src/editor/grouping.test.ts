// @vitest-environment jsdom
import { describe, expect, it } from 'vitest';
import { groupIntoSubsystem } from './grouping';

const hmf = `<?xml version="1.0" encoding="UTF-8"?>
<hopsanmodelfile hmfversion="0.4">
  <system typename="Subsystem" name="Root">
    <simulationtime stop="1" timestep="0.001" start="0" inherit_timestep="true"/>
    <objects>
      <component typename="SignalStep" name="Step"><hopsangui><pose x="0" y="0" a="0" flipped="false"/></hopsangui></component>
      <component typename="SignalGain" name="Gain"><hopsangui><pose x="100" y="0" a="0" flipped="false"/></hopsangui></component>
      <component typename="SignalGain" name="Gain2"><hopsangui><pose x="200" y="0" a="0" flipped="false"/></hopsangui></component>
      <component typename="SignalSink" name="Scope"><hopsangui><pose x="300" y="0" a="0" flipped="false"/></hopsangui></component>
    </objects>
    <connections>
      <connect startcomponent="Step" startport="out" endcomponent="Gain" endport="in">
        <hopsangui><coordinates><coordinate x="20" y="0"/><coordinate x="80" y="0"/></coordinates></hopsangui>
      </connect>
      <connect startcomponent="Gain" startport="out" endcomponent="Gain2" endport="in"/>
      <connect startcomponent="Gain2" startport="out" endcomponent="Scope" endport="in"/>
      <connect startcomponent="Gain2" startport="out" endcomponent="Scope" endport="in_right"/>
    </connections>
  </system>
</hopsanmodelfile>`;

function parse(text: string): Document {
    return new DOMParser().parseFromString(text, 'application/xml');
}

describe('groupIntoSubsystem', () => {
    it('moves the selection and its inner connections into a new subsystem', () => {
        const grouped = groupIntoSubsystem(hmf, [], ['Gain', 'Gain2']);
        expect(grouped.subsystemName).toBe('Subsystem');
        const doc = parse(grouped.hmf);
        const root = doc.querySelector('hopsanmodelfile > system')!;
        const outer = Array.from(root.querySelector(':scope > objects')!.children).map((e) => e.getAttribute('name'));
        expect(outer).toEqual(['Step', 'Scope', 'Subsystem']);
        const sub = root.querySelector(':scope > objects > system[name="Subsystem"]')!;
        const inner = Array.from(sub.querySelector(':scope > objects')!.children).map((e) => `${e.tagName}:${e.getAttribute('name')}`);
        expect(inner).toEqual(['systemport:Gain2_out', 'systemport:Gain_in', 'component:Gain', 'component:Gain2']);
        // centre of the grouped components
        const pose = sub.querySelector(':scope > hopsangui > pose')!;
        expect(pose.getAttribute('x')).toBe('150');
    });

    it('routes cut connections through one system port per inner port', () => {
        const doc = parse(groupIntoSubsystem(hmf, [], ['Gain', 'Gain2']).hmf);
        const root = doc.querySelector('hopsanmodelfile > system')!;
        const ends = (c: Element) => `${c.getAttribute('startcomponent')}.${c.getAttribute('startport')}-${c.getAttribute('endcomponent')}.${c.getAttribute('endport')}`;
        const outer = Array.from(root.querySelectorAll(':scope > connections > connect')).map(ends);
        expect(outer).toEqual(['Step.out-Subsystem.Gain_in', 'Subsystem.Gain2_out-Scope.in', 'Subsystem.Gain2_out-Scope.in_right']);
        const inner = Array.from(root.querySelectorAll(':scope > objects > system > connections > connect')).map(ends);
        expect(inner).toEqual(['Gain.in-Gain_in.Gain_in', 'Gain.out-Gain2.in', 'Gain2.out-Gain2_out.Gain2_out']);
        // the stale drawn line of a cut connection is dropped
        expect(root.querySelector(':scope > connections > connect hopsangui')).toBeNull();
    });

    it('refuses a selection that is not in the file', () => {
        expect(() => groupIntoSubsystem(hmf, [], ['Nope'])).toThrow(/none of the selected/);
        expect(() => groupIntoSubsystem(hmf, ['Missing'], ['Gain'])).toThrow(/no subsystem/);
    });
});
