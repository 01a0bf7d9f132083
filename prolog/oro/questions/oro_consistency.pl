:- module(oro_consistency,
          [ oro_consistent/1,           % +Model
            oro_conflict/2,             % +Model, -Conflict
            oro_consistent_with/2,      % +Model, +Statements
            oro_safe_add/4,             % +Model, +Statements, +Profile, -Accepted
            oro_declared_different/3    % +Model, ?X, ?Y
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(ordsets)).
:- use_module(library(pairs)).
:- use_module(library(debug)).
:- use_module(library(aggregate)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/parse/oro_parse)).
:- use_module(library(oro/oro_memory)).

/** <module> Consistency: a robot must not believe a cow is a plant

A model is inconsistent when its inference closure contradicts an axiom
of its schema.  oro_conflict/2 finds the contradictions oro checks:

  - an individual in two disjoint classes (owl:disjointWith, either
    way, and the members of owl:AllDisjointClasses), or in a class and
    its owl:complementOf, or in owl:Nothing;
  - two different values of an owl:FunctionalProperty for one subject,
    or two different subjects with one value of an
    owl:InverseFunctionalProperty.  Literals differ when their values
    differ; individuals only when declared different (owl:differentFrom,
    owl:AllDifferent): OWL makes no unique-name assumption;
  - individuals both owl:sameAs and owl:differentFrom each other;
  - `x p x` for an owl:IrreflexiveProperty, `x p y` and `y p x` for an
    owl:AsymmetricProperty, and `x p y` with `x q y` for
    p owl:propertyDisjointWith q (or both in owl:AllDisjointProperties).

Types and values are those of the inference closure (oro_reason), so a
conflict through domains, ranges, sub-classes and the OWL 2 RL class
expressions (a hasValue restriction giving a second value of a
functional property, an intersection of disjoint classes, ...) is found
as well.  An inconsistent model stays usable: every question is still
answered over what is there; only safeAdd refuses to add to it.

## Literal values

Two literal values of a functional (or inverse functional) property
clash when their *values* differ, compared as oro_literal_match/2
does: numbers numerically whatever their numeric datatype, booleans by
truth value (`true` and `1`), strings by their text (a plain literal,
an xsd:string and a language-tagged string with the same text are the
same value).  So `bob birthYear 1990` and `bob birthYear
"1990.0"^^xsd:double` are one value, not a conflict.  This is a
deliberate departure from OWL 2, where xsd:integer and xsd:double have
disjoint value spaces (and "chat"@en differs from "chat"@fr), which
would make that pair inconsistent.  The reasons:

  - the protocol is text: a client writes `age 12`, `weight 99.5` or
    `weight 99` and the datatype follows from how the number happens to
    be spelt (ORO-SPEC §4.2), not from what the client means; find and
    getInfos answer bare lexical forms, without datatypes, so a client
    reading a value back and re-adding it may change its datatype;
  - check and find match literals by value, as ORO-SPEC
    §4.3 recommends (numbers and booleans by value, strings by lexical
    form ignoring language and xsd:string) and as the original's Jena
    graphs did for numbers; oro_literal_match/2 is the reasoner's own
    comparison.  A model declared inconsistent over two values that
    every pattern calls equal would leave a robot unable to tell the
    culprit apart.

Language tags are ignored for the same reason: they cannot be written
through the protocol (ORO-SPEC §4.2), only read from ontology files.

## Cost

A full check (conflict/2 for every kind) enumerates the instances of
each disjoint class and the values of each property with a
characteristic, linear in their number.  Its verdict is remembered for
the model and the rdf_db generation it was made at (rdf_generation/1
changes with every committed change), so asking again before anything
changed costs nothing.

After a change, checkConsistency and safeAdd do not start again from
nothing: the *delta log* (below) holds the triples each transaction
added to and removed from each model since the remembered verdict,
and:

  - if the model was consistent, only the added triples are checked,
    incrementally (as below); removed ones need no check;
  - if it was inconsistent and nothing was removed, it still is;
  - otherwise, and whenever the log cannot tell (no verdict yet, more
    than 1,000 triples added, a schema triple added or removed, a
    change the log could not follow), a full check is made.

safeAdd and checkConsistency(Statements) check the statements they add
*incrementally* once the model is known to be consistent before the
change: only the individuals the new statements can affect are checked
(their types, their values and the values pointing to them).  The
affected set is the subjects and objects of the new statements (and
their owl:sameAs individuals), grown along what can carry a change to
another individual: the transitive properties that imply a property
some check or class expression looks at (the whole chain up and down),
the properties of someValuesFrom and allValuesFrom restrictions,
property chains and hasValue values.  A full check is made instead when
a new statement changes the schema (oro_store's schema triples) or
declares individuals different (owl:differentFrom, owl:AllDifferent,
owl:AllDisjointClasses, owl:members, owl:distinctMembers), or when the
affected set exceeds 5,000 individuals.

### Why removals need no check

Every kind of conflict is an existential statement over the inference
closure and the declared differences: some `x` in two disjoint classes
(or a class and its complement, or owl:Nothing); some `x p v1`, `x p
v2` with `v1`, `v2` different; some `x owl:sameAs y` with `x`, `y`
declared different; some `x p x`, `x p y` with `y p x`, `x p y` with
`x q y`.  Each is true as long as the triples of one derivation are
there, and removing a triple can only take derivations away:

  - the closure is monotone: RDFS, the property axioms and the OWL 2 RL
    rules oro_reason applies (cls-int1/2, cls-uni, cls-hv1/2,
    cls-svf1/2, cls-avf, cls-oo, prp-spo2, sub-properties, inverses,
    symmetry, transitivity, domains, ranges, owl:sameAs) are Horn rules
    without negation, so a smaller set of triples has a smaller closure.
    The bounds of oro_reason's search (a goal already in progress
    fails, derivations stop 64 levels deep) do not depend on the
    triples; where they make it incomplete (see its module doc), a
    full check is no better;
  - declared differences (owl:differentFrom, owl:AllDifferent) are
    asserted triples: fewer triples, fewer differences;
  - the remaining tests are on the terms alone: literal values
    (different/3), blank nodes (not reported), and a literal always
    differs from a resource.

The one non-monotone inference oro_reason makes, a property's kind
taken from its values (oro_property/3: `datatype` if it has a literal
value), is not used by any check.  Schema triples are monotone too,
but a change of them changes the compiled schema closures a check
relies on (and the affected-set spreading), so the log never carries
a verdict across one: it forces a full check, added or removed.

### The delta log

An rdf_monitor/2 callback, registered when the first verdict is
remembered (loading this module registers nothing), is called by the
writing thread as a transaction commits.  It only records, with no
lock and no consistency work: logged/6 facts of the generation, model
and sign of each triple of a model graph (a triple put in a model's
mask is a removal, one taken out of it an addition).  It records
nothing while no verdict is remembered, starts only at the beginning of
a commit, drops the generations no remembered verdict needs at the
next commit, and turns itself off past 20,000 triples, on a change it
cannot follow triple by triple (a write outside a transaction,
rdf_update, loading a file, a change of the ontology layer or of a
graph of no model, as when models are wiped) or on a
generation it did not see, so what it holds is always the exact set of
changes between two generations.  A reader checks the log covers the
generations it needs, reads them, and checks the log was not emptied
or pruned meanwhile.

Measured by bench/bench_consistency.pl (common-sense ontology, the
bench world, medians on a busy 2-core VM): a full check 7 ms at 10k
asserted triples, 50 to 76 ms at 100k (mostly enumerating the values
of the functional properties hasColor and isVisible); checkConsistency
after a plain add of one statement 0.3 to 0.4 ms at both sizes (it was
a full check), after a remove 9 us, unchanged 1 us; safeAdd of one
statement 0.2 to 0.4 ms, accepted or rejected, and 0.7 to 0.9 ms right
after a plain add (it was a full check too).  The log costs an add
about 1 to 2 us while a verdict is remembered; otherwise its callback
returns at once.

The verdict cache is this module's state: verdict/3 facts, written
under the `oro_consistency` mutex, only outside transactions (or, in
safeAdd, in the module's own transaction while it has changed nothing),
where the generation identifies exactly what the check saw.  The delta
log is state of its own, written by the monitor callback alone (see
the comments opening the DELTA LOG section of the code).
*/

:- rdf_meta
    trigger(r, o).

:- dynamic
    verdict/3.                      % Model, Generation, Consistent

%!  oro_consistent(+Model) is semidet.
%
%   Model has no conflict.

oro_consistent(Model0) :-
    oro_resolve_model(Model0, Model),
    consistent_now(Model).

%!  oro_conflict(+Model, -Conflict) is nondet.
%
%   Conflict is a contradiction of Model: disjoint(X, C1, C2) (C1 @<
%   C2), nothing(X), functional(P, X, V1, V2), inverse_functional(P, V,
%   X1, X2), same_and_different(X, Y), irreflexive(P, X), asymmetric(P,
%   X, Y) or disjoint_properties(P, Q, X, Y) (P @< Q).

oro_conflict(Model0, Conflict) :-
    oro_resolve_model(Model0, Model),
    conflict(Model, Conflict).

		 /*******************************
		 *          FULL CHECK          *
		 *******************************/

conflict(Model, disjoint(X, C1, C2)) :-
    findall(A-B, ( oro_disjoint_classes(Model, A, B),
                   A @< B
                 ), Pairs0),
    sort(Pairs0, Pairs),
    findall(C, ( member(A-B, Pairs), ( C = A ; C = B ) ), Classes0),
    sort(Classes0, Classes),
    findall(C-Xs, ( member(C, Classes),
                    instances(Model, C, Xs)
                  ), ClassInstances),       % each class once
    member(C1-C2, Pairs),
    memberchk(C1-Xs1, ClassInstances),
    Xs1 \== [],
    memberchk(C2-Xs2, ClassInstances),
    ord_intersection(Xs1, Xs2, Both),
    member(X, Both),
    \+ rdf_is_bnode(X).
conflict(Model, nothing(X)) :-
    rdf_equal(owl:'Nothing', Nothing),
    instances(Model, Nothing, Xs),
    member(X, Xs),
    \+ rdf_is_bnode(X).
conflict(Model, functional(P, X, V1, V2)) :-
    characteristic(Model, functional, P),
    findall(X0-V, oro_holds(Model, X0, P, V), Pairs),  % ordered by X0, V
    shared_key(Pairs, X, Vs),
    two_different(Model, Vs, V1, V2).
conflict(Model, inverse_functional(P, V, X1, X2)) :-
    characteristic(Model, inverse_functional, P),
    findall(V0-X, oro_holds(Model, X, P, V0), Pairs0),
    msort(Pairs0, Pairs),
    shared_key(Pairs, V, Xs),
    two_different(Model, Xs, X1, X2).
conflict(Model, same_and_different(X, Y)) :-
    different_pairs(Model, Pairs),
    member(X-Y, Pairs),
    oro_same_individual(Model, X, Y).
conflict(Model, irreflexive(P, X)) :-
    characteristic(Model, irreflexive, P),
    oro_holds(Model, X, P, X).
conflict(Model, asymmetric(P, X, Y)) :-
    characteristic(Model, asymmetric, P),
    oro_holds(Model, X, P, Y),
    oro_holds(Model, Y, P, X).
conflict(Model, disjoint_properties(P, Q, X, Y)) :-
    findall(A-B, ( oro_disjoint_properties(Model, A, B),
                   A @< B
                 ), Pairs0),
    sort(Pairs0, Pairs),
    member(P-Q, Pairs),
    oro_holds(Model, X, P, Y),
    oro_holds(Model, X, Q, Y).

instances(Model, C, Xs) :-
    findall(X, oro_type(Model, X, C), Xs).    % ordered: oro_holds sorts

characteristic(Model, Char, P) :-
    findall(P0, oro_property_characteristic(Model, P0, Char), Ps0),
    sort(Ps0, Ps),
    member(P, Ps).

%   shared_key(+Pairs, -Key, -Values): Key has two values or more in
%   the ordered Key-Value list Pairs; one linear scan, most keys having
%   one value.

shared_key([K-V|Pairs], Key, Values) :-
    same_key_values(Pairs, K, Vs, Rest),
    (   Vs \== [],
        Key = K,
        Values = [V|Vs]
    ;   shared_key(Rest, Key, Values)
    ).

same_key_values([K1-V|Pairs], K, [V|Vs], Rest) :-
    K1 == K,
    !,
    same_key_values(Pairs, K, Vs, Rest).
same_key_values(Pairs, _, [], Pairs).

%   two_different(+Model, +Values, -V1, -V2): two values of the list
%   that differ (V1 before V2).

two_different(Model, Values, V1, V2) :-
    append(_, [V1|Rest], Values),
    member(V2, Rest),
    V1 \== V2,
    different(Model, V1, V2),
    !.

different(Model, V1, V2) :-
    (   V1 = literal(_), V2 = literal(_)
    ->  \+ oro_literal_match(V1, V2)
    ;   V1 = literal(_)
    ->  true
    ;   V2 = literal(_)
    ->  true
    ;   oro_declared_different(Model, V1, V2)
    ).

%!  oro_declared_different(+Model, ?X, ?Y) is nondet.
%
%   X and Y, or individuals owl:sameAs them, are declared different
%   (owl:differentFrom either way, or members of one owl:AllDifferent).
%   Semidet when X and Y are bound; with X or Y unbound, enumerates the
%   declared pairs themselves, both ways.

oro_declared_different(Model0, X, Y) :-
    oro_resolve_model(Model0, Model),
    different_pairs(Model, Pairs),
    (   nonvar(X), nonvar(Y)
    ->  oro_same_individual(Model, X, X1),
        oro_same_individual(Model, Y, Y1),
        (   ord_memberchk(X1-Y1, Pairs)
        ->  true
        ;   ord_memberchk(Y1-X1, Pairs)
        ),
        !
    ;   member(A-B, Pairs),
        (   X-Y = A-B
        ;   X-Y = B-A
        )
    ).

different_pairs(Model, Pairs) :-
    rdf_equal(owl:differentFrom, DF),
    findall(A-B, ( oro_asserted(Model, A, DF, B)
                 ; all_different(Model, A, B)
                 ), Pairs0),
    sort(Pairs0, Pairs).

all_different(Model, A, B) :-
    rdf_equal(rdf:type, Type),
    rdf_equal(owl:'AllDifferent', All),
    oro_asserted(Model, Axiom, Type, All),
    (   rdf_equal(owl:distinctMembers, P)
    ;   rdf_equal(owl:members, P)
    ),
    oro_asserted(Model, Axiom, P, List),
    oro_rdf_list(Model, List, Members),
    append(_, [A|Rest], Members),
    member(B, Rest).


		 /*******************************
		 *        VERDICT CACHE         *
		 *******************************/

%   consistent_now(+Model): the verdict remembered for the current
%   generation, or a check (incremental if it can be, see check_at/3).
%   The cache is used outside transactions only: there the generation
%   names exactly what is visible.

consistent_now(Model) :-
    (   \+ rdf_active_transaction(_),
        rdf_generation(Gen),
        integer(Gen)
    ->  consistent_at(Model, Gen)
    ;   \+ conflict(Model, _)
    ).

%   consistent_at(+Model, +Gen): Model is consistent at generation Gen
%   (what this thread sees now).

consistent_at(Model, Gen) :-
    (   verdict(Model, Gen, Verdict)
    ->  true
    ;   check_at(Model, Gen, Verdict),
        remember(Model, Gen, Verdict)
    ),
    Verdict == true.

%   check_at(+Model, +Gen, -Verdict): check Model at generation Gen.
%   From the verdict remembered at an earlier generation Gen0 and the
%   changes logged since (delta log, below): consistent then and only
%   additions checked incrementally now, or inconsistent then and
%   nothing removed since.  Else (no earlier verdict, the log does not
%   cover the changes, a schema change, too many changes) a full check.

check_at(Model, Gen, Verdict) :-
    (   verdict(Model, Gen0, Verdict0),
        Gen0 < Gen,
        logged_changes(Model, Gen0, Gen, Added, Removed),
        (   Verdict0 == true
        ->  How = incremental(Added)
        ;   Removed == []
        ->  How = unchanged
        )
    ->  true
    ;   How = full
    ),
    how_verdict(How, Model, Verdict),
    functor(How, Kind, _),
    debug(oro(consistency), 'Model ~q at generation ~q: consistent ~q (~q check)',
          [Model, Gen, Verdict, Kind]).

how_verdict(incremental(Added), Model, Verdict) :-
    (   new_conflict(Model, Added)
    ->  Verdict = false
    ;   Verdict = true
    ).
how_verdict(unchanged, _, false).
how_verdict(full, Model, Verdict) :-
    (   conflict(Model, _)
    ->  Verdict = false
    ;   Verdict = true
    ).

remember(Model, Gen, Verdict) :-
    with_mutex(oro_consistency,
               ( retractall(verdict(Model, _, _)),
                 assertz(verdict(Model, Gen, Verdict)),
                 log_keep
               )),
    debug(oro(consistency), 'Model ~q at generation ~q: remembered ~q',
          [Model, Gen, Verdict]).

%   own_generation(+Action, -Gen): inside the transaction of Action,
%   which has changed nothing yet and is the only one active, Gen is
%   the generation the thread sees.  Fails otherwise.

own_generation(Action, Gen) :-
    findall(T, rdf_active_transaction(T), [oro(Action)]),
    rdf_generation(Gen),
    integer(Gen).

consistent_before(Action, Model) :-
    (   own_generation(Action, Gen)
    ->  consistent_at(Model, Gen)
    ;   \+ conflict(Model, _)
    ).

%   After a commit: if the generation is exactly one more than Gen0
%   (nothing else committed meanwhile), remember Verdict for it.

remember_after(Model, Gen0, Verdict) :-
    (   integer(Gen0),
        \+ rdf_active_transaction(_),
        rdf_generation(Gen),
        integer(Gen),
        (   Gen =:= Gen0 + 1
        ;   Gen =:= Gen0
        )
    ->  remember(Model, Gen, Verdict)
    ;   true
    ).

		 /*******************************
		 *          DELTA LOG           *
		 *******************************/

%   The delta log holds the triples each committed transaction added to
%   or removed from each model, by generation, for as long as a
%   remembered verdict may need them: logged(Gen, Model, Sign, S, P, O)
%   with Sign `add` or `del` (a triple put in a model's mask is removed
%   from it, one taken out of the mask is added to it).
%
%   It is fed by an rdf_monitor/2 callback, registered when the first
%   verdict is remembered and run by the writing thread as each
%   transaction commits (writers are serialised: oro_store's
%   `oro_write` mutex, rdf_db's commit).  The callback only records:
%   it is total, takes no lock and never blocks.  Its state, written
%   by the callback alone, is in flags:
%
%     - `oro_consistency_log_from`: the log holds every change made
%       after this generation, -1 when it is off;
%     - `oro_consistency_log_done`: the last generation whose commit
%       was logged completely;
%     - `oro_consistency_log_size`: the number of logged/6 facts, at
%       most max_log/1 (past it the log is off until a verdict is
%       remembered again);
%     - `oro_consistency_log_epoch`: bumped whenever the log is
%       emptied, so that a reader notices it was emptied under it.
%
%   `oro_consistency_log_keep` is written by remember/3 (under the
%   `oro_consistency` mutex): the oldest generation a remembered
%   verdict may want the changes since, or -1 for none (then the
%   callback records nothing); the callback sets it to -1 when the log
%   overflows, as no verdict remembered then can be served any more.  The log starts, and drops what no
%   verdict needs any more, at the beginning of a commit only, so it
%   always starts at a commit boundary.  A change the callback cannot
%   follow triple by triple (a write outside a transaction, an
%   rdf_update, loading a file, a change of the ontology layer, a
%   generation it did not see) or a change of a graph that is not a
%   model's (the graphs of a model being wiped, which are unmapped
%   first; a scratch graph) turns the log off: the checks that would
%   have needed it are full checks.

:- dynamic
    logged/6,                       % Generation, Model, add|del, S, P, O
    log_monitor_started/0.

max_log(20000).

%   logged_changes(+Model, +Gen0, +Gen, -Added, -Removed) is semidet:
%   the triples added to and removed from Model by the transactions
%   committed after generation Gen0 up to Gen (ordered sets).  Fails if
%   the log does not hold all of them, if one is a schema triple (the
%   schema closures a check uses changed), or if more than max_delta/1
%   were added.

logged_changes(Model, Gen0, Gen, Added, Removed) :-
    flag(oro_consistency_log_epoch, Epoch, Epoch),
    flag(oro_consistency_log_from, From, From),
    flag(oro_consistency_log_done, Done, Done),
    From >= 0,
    From =< Gen0,
    Done =:= Gen,
    max_log(MaxLog),
    Gen - Gen0 =< MaxLog,
    G1 is Gen0 + 1,
    findall(Sign-rdf(S, P, O),
            ( between(G1, Gen, G),
              logged(G, Model, Sign, S, P, O)
            ), Changes),
    flag(oro_consistency_log_epoch, Epoch, Epoch),  % not emptied meanwhile
    flag(oro_consistency_log_from, From1, From1),   % nor pruned past Gen0
    From1 >= 0,
    From1 =< Gen0,
    \+ ( member(_-rdf(_, P, O), Changes),
         oro_schema_triple(P, O)
       ),
    findall(T, member(add-T, Changes), Added0),
    sort(Added0, Added),
    length(Added, N),
    max_delta(MaxDelta),
    N =< MaxDelta,
    findall(T, member(del-T, Changes), Removed0),
    sort(Removed0, Removed).

max_delta(1000).

%   log_keep: called by remember/3 under the mutex.  The log is wanted
%   from the oldest remembered verdict it can still serve (verdicts
%   older than the log's start are left to full checks).

log_keep :-
    flag(oro_consistency_log_from, From, From),
    (   aggregate_all(min(G), ( verdict(_, G, _),
                                G >= From
                              ), Keep)
    ->  ensure_log_monitor,
        flag(oro_consistency_log_keep, _, Keep)
    ;   flag(oro_consistency_log_keep, _, -1)
    ).

ensure_log_monitor :-
    (   log_monitor_started
    ->  true
    ;   flag(oro_consistency_log_from, _, -1),
        log_monitor_mask(Mask),
        rdf_monitor(oro_consistency:log_monitor, Mask),
        assertz(log_monitor_started)
    ).

log_monitor_mask([ -all, +assert, +retract, +update, +transaction,
                   +load, +reset
                 ]).

%   A store rebuild (oro_store_rebuild/0) empties rdf_db and fills it
%   again: the log does not see it, and the verdicts, made at rdf_db
%   generations that start again from 0, are forgotten.

:- multifile oro_store:rebuild_hook/1.

oro_store:rebuild_hook(suspend) :-
    (   log_monitor_started
    ->  rdf_monitor(oro_consistency:log_monitor, [-all])
    ;   true
    ).
oro_store:rebuild_hook(resume) :-
    with_mutex(oro_consistency,
               ( retractall(verdict(_, _, _)),
                 log_off
               )),
    (   log_monitor_started
    ->  log_monitor_mask(Mask),
        rdf_monitor(oro_consistency:log_monitor, Mask)
    ;   true
    ).

%   log_monitor(+Event): the rdf_monitor/2 callback.

:- public log_monitor/1.

log_monitor(Event) :-
    catch(log_event(Event), E, log_failed(E)),
    !.
log_monitor(_).

log_failed(E) :-
    catch(log_off_now, _, true),
    print_message(warning, E).

log_event(transaction(begin(0), _)) :-
    !,
    rdf_generation(G),
    generation_base(G, Base),
    (   log_boundary(Base)
    ->  Next is Base + 1,
        set_committing(Next)
    ;   set_committing(none)
    ).
log_event(transaction(end(0), _)) :-
    !,
    (   committing(Next),
        integer(Next)
    ->  set_committing(outside),
        rdf_generation(G),
        (   integer(G),
            G >= Next - 1,                  % Next - 1: nothing changed
            G =< Next
        ->  flag(oro_consistency_log_done, _, G)
        ;   log_off
        )
    ;   set_committing(outside)
    ).
log_event(transaction(_, _)) :-
    !.
log_event(assert(S, P, O, Source)) :-
    !,
    log_triple(add, S, P, O, Source).
log_event(retract(S, P, O, Source)) :-
    !,
    log_triple(del, S, P, O, Source).
log_event(_) :-                         % update, load, reset
    log_off_now.

%   committing(-Next): a transaction is being committed, whose changes
%   are logged as those of generation Next (`none`: not logged).  What
%   the writing thread commits is its global variable
%   oro_consistency_committing (`outside` between commits), not a
%   fact: a clause retracted by every write is work for the clause
%   garbage collector (see oro_store, "Writes leave no clause behind").

committing(Next) :-
    nb_current(oro_consistency_committing, Next),
    Next \== outside.

set_committing(Next) :-
    nb_setval(oro_consistency_committing, Next).

%   Inside a transaction being committed, the generation is Base+N.

generation_base(Base+_, Base) :-
    !.
generation_base(Gen, Gen).

%   log_boundary(+Base) is semidet: a transaction is about to commit
%   over generation Base; succeeds if its changes are to be logged
%   (as those of generation Base+1).

log_boundary(Base) :-
    flag(oro_consistency_log_keep, Keep, Keep),
    flag(oro_consistency_log_from, From, From),
    (   \+ integer(Base)
    ->  log_off,
        fail
    ;   Keep < 0
    ->  (   From >= 0
        ->  log_off
        ;   true
        ),
        fail
    ;   From < 0
    ->  log_on(Base)
    ;   flag(oro_consistency_log_done, Done, Done),
        Done =\= Base                       % a change went by unseen
    ->  log_off,
        log_on(Base)
    ;   Keep > From
    ->  log_prune(From, Keep)
    ;   true
    ).

log_on(Base) :-
    retractall(logged(_, _, _, _, _, _)),
    flag(oro_consistency_log_size, _, 0),
    flag(oro_consistency_log_done, _, Base),
    flag(oro_consistency_log_from, _, Base),
    flag(oro_consistency_log_epoch, E, E+1).

log_off :-
    flag(oro_consistency_log_from, _, -1),
    flag(oro_consistency_log_epoch, E, E+1),
    retractall(logged(_, _, _, _, _, _)),
    flag(oro_consistency_log_size, _, 0).

%   log_off_now: turn the log off, and if a commit is being logged,
%   log nothing more of it.

log_off_now :-
    flag(oro_consistency_log_from, From, From),
    (   From >= 0
    ->  log_off
    ;   true
    ),
    (   committing(_)
    ->  set_committing(none)
    ;   true
    ).

%   log_prune(+From, +Keep): drop the changes of the generations up to
%   Keep, which no remembered verdict needs.  The start moves first, so
%   a reader of those generations sees they are gone.

log_prune(From, Keep) :-
    flag(oro_consistency_log_from, _, Keep),
    G1 is From + 1,
    forall(between(G1, Keep, G),
           (   aggregate_all(count, logged(G, _, _, _, _, _), N),
               N > 0
           ->  retractall(logged(G, _, _, _, _, _)),
               flag(oro_consistency_log_size, S, S-N)
           ;   true
           )).

%   log_triple(+Sign, +S, +P, +O, +Source): a triple of Source was
%   added or removed, by the transaction being committed if any.

log_triple(Sign, S, P, O, Source) :-
    (   committing(Next)
    ->  (   Next == none
        ->  true
        ;   source_graph(Source, Graph),
            log_graph_triple(Graph, Next, Sign, S, P, O)
        )
    ;   log_off_now                         % a write outside a transaction
    ).

log_graph_triple(Graph, Gen, Sign0, S, P, O) :-
    (   oro_graph_layer(Graph, Model, Layer)
    ->  layer_sign(Layer, Sign0, Sign),
        assertz(logged(Gen, Model, Sign, S, P, O)),
        flag(oro_consistency_log_size, N, N+1),
        max_log(Max),
        (   N < Max
        ->  true
        ;   log_off_now,
            flag(oro_consistency_log_keep, _, -1)
        )
    ;   log_off_now                         % the ontology layer, or a graph
    ).                                      % of no model (a model wiped)

source_graph(Graph:_, Graph) :-
    !.
source_graph(Graph, Graph).

layer_sign(mask, add, del) :-
    !.
layer_sign(mask, del, add) :-
    !.
layer_sign(_, Sign, Sign).

		 /*******************************
		 *      INCREMENTAL CHECK       *
		 *******************************/

%   new_conflict(+Model, +Triples): Model, consistent before the
%   triples Triples were added to it, is not any more.

new_conflict(_, []) :-
    !,
    fail.
new_conflict(Model, Triples) :-
    (   member(rdf(_, P, O), Triples),
        (   oro_schema_triple(P, O)
        ;   trigger(P, O)
        )
    ->  debug(oro(consistency), 'Full check: schema or difference change', []),
        conflict(Model, _)
    ;   affected(Model, Triples, Affected)
    ->  checks(Model, Checks),
        member(X, Affected),
        individual_conflict(Model, Checks, X, _)
    ;   debug(oro(consistency), 'Full check: too many affected individuals', []),
        conflict(Model, _)
    ),
    !.

trigger(owl:differentFrom, _).
trigger(owl:distinctMembers, _).
trigger(owl:members, _).
trigger(rdf:type, owl:'AllDifferent').
trigger(rdf:type, owl:'AllDisjointClasses').
trigger(rdf:type, owl:'AllDisjointProperties').

max_affected(5000).

%   affected(+Model, +Triples, -Affected) is semidet: the individuals
%   whose types or values the triples may have changed; fails if there
%   are more than max_affected/1.

affected(Model, Triples, Affected) :-
    rdf_equal(rdf:type, Type),
    findall(X, ( member(rdf(S, P, O), Triples),
                 (   X0 = S
                 ;   P \== Type,
                     atom(O),
                     X0 = O
                 ),
                 oro_same_individual(Model, X0, X)
               ), Seeds0),
    sort(Seeds0, Seeds),
    spreading(Model, Spread),
    (   Spread = spread([], [], [], [], [])
    ->  Affected = Seeds
    ;   max_affected(Max),
        findall(X-seed, member(X, Seeds), Queue),
        spread(Queue, Model, Spread, Seeds, Max, Affected)
    ).

%   spreading(+Model, -Spread): what carries a change from an
%   individual to others: spread(Transitive, Some, All, Values, Chains)
%   with the transitive properties to follow both ways, the properties
%   to follow backwards (someValuesFrom) and forwards (allValuesFrom),
%   the resource values of hasValue restrictions, and the link
%   properties of chains with the chain length.

spreading(Model, spread(Ts, Somes, Alls, Values, Chains)) :-
    findall(P, sensitive_property(Model, P), Ps0),
    sort(Ps0, Ps),
    findall(T, ( member(P, Ps),
                 oro_property_way(Model, P, T, _),
                 oro_transitive_property(Model, T)
               ), Ts0),
    sort(Ts0, Ts),
    findall(Q, oro_class_definition(Model, _, some_values(Q, class(_))), Somes0),
    sort(Somes0, Somes),
    findall(Q, oro_class_definition(Model, _, all_values(Q, class(_))), Alls0),
    sort(Alls0, Alls),
    findall(V, ( oro_class_definition(Model, _, has_value(_, V)),
                 atom(V)
               ), Values0),
    sort(Values0, Values),
    findall(N-Links, ( oro_property_chain(Model, _, Links),
                       length(Links, N)
                     ), Chains0),
    sort(Chains0, Chains).

sensitive_property(Model, P) :-
    oro_property_characteristic(Model, P, _).
sensitive_property(Model, P) :-
    oro_disjoint_properties(Model, P, _).
sensitive_property(Model, P) :-
    oro_class_definition(Model, _, Def),
    arg(1, Def, P),
    atom(P),
    functor(Def, Name, 2),
    memberchk(Name, [has_value, some_values, all_values]).
sensitive_property(Model, P) :-
    oro_property_chain(Model, _, Links),
    member(Link, Links),
    (   Link = inverse(P)
    ->  true
    ;   P = Link
    ).

%   spread(+Queue, +Model, +Spread, +Seen, +Max, -Affected): breadth
%   first.  Queue holds X-How: `seed` individuals spread along
%   transitive properties, those reached that way do not (their chain
%   is the one already followed).

spread([], _, _, Seen, _, Seen).
spread([X-How|Queue], Model, Spread, Seen, Max, Affected) :-
    findall(Y-How1, neighbour(Model, Spread, How, X, Y, How1), Next0),
    sort(Next0, Next1),
    exclude(seen(Seen), Next1, Next),
    pairs_keys(Next, New0),
    sort(New0, New),
    ord_union(Seen, New, Seen1),
    length(Seen1, N),
    N =< Max,
    append(Queue, Next, Queue1),
    spread(Queue1, Model, Spread, Seen1, Max, Affected).

seen(Seen, Y-_) :-
    ord_memberchk(Y, Seen).

neighbour(Model, spread(Ts, _, _, _, _), seed, X, Y, closure) :-
    member(T, Ts),
    (   oro_holds(Model, Y, T, X)
    ;   oro_holds(Model, X, T, Y)
    ),
    atom(Y).
neighbour(Model, spread(_, Somes, _, _, _), _, X, Y, seed) :-
    member(Q, Somes),
    oro_holds(Model, Y, Q, X),
    atom(Y).
neighbour(Model, spread(_, _, Alls, _, _), _, X, Y, seed) :-
    member(Q, Alls),
    oro_holds(Model, X, Q, Y),
    atom(Y).
neighbour(_, spread(_, _, _, Values, _), _, _, Y, seed) :-
    member(Y, Values).
neighbour(Model, spread(_, _, _, _, Chains), _, X, Y, seed) :-
    member(N-Links, Chains),
    chain_neighbour(Model, Links, N, X, Y).

%   Anything within N link steps, either way, of X.

chain_neighbour(Model, Links, N, X, Y) :-
    findall(P, ( member(L, Links),
                 (   L = inverse(P)
                 ->  true
                 ;   P = L
                 )
               ), Ps0),
    sort(Ps0, Ps),
    chain_ball(Model, Ps, N, [X], [X], Ball),
    member(Y, Ball),
    Y \== X.

chain_ball(_, _, 0, _, Ball, Ball) :-
    !.
chain_ball(Model, Ps, N, Frontier, Ball0, Ball) :-
    findall(Y, ( member(X, Frontier),
                 member(P, Ps),
                 (   oro_holds(Model, X, P, Y)
                 ;   oro_holds(Model, Y, P, X)
                 ),
                 atom(Y)
               ), Ys0),
    sort(Ys0, Ys),
    ord_subtract(Ys, Ball0, New),
    ord_union(Ball0, New, Ball1),
    N1 is N - 1,
    (   New == []
    ->  Ball = Ball1
    ;   chain_ball(Model, Ps, N1, New, Ball1, Ball)
    ).

%   checks(+Model, -Checks): the axioms an individual is checked
%   against.

checks(Model, checks(Functional, InverseFunctional, Irreflexive,
                     Asymmetric, DisjointProperties)) :-
    findall(P, characteristic(Model, functional, P), Functional),
    findall(P, characteristic(Model, inverse_functional, P),
            InverseFunctional),
    findall(P, characteristic(Model, irreflexive, P), Irreflexive),
    findall(P, characteristic(Model, asymmetric, P), Asymmetric),
    findall(P-Q, oro_disjoint_properties(Model, P, Q), DisjointProperties0),
    sort(DisjointProperties0, DisjointProperties).

%   individual_conflict(+Model, +Checks, +X, -Conflict): a conflict
%   about X: its types, its values, the subjects sharing a value of X
%   or pointing to X by an inverse functional property.

individual_conflict(Model, _, X, Conflict) :-
    findall(C, oro_type(Model, X, C), Types),
    rdf_equal(owl:'Nothing', Nothing),
    (   ord_memberchk(Nothing, Types)
    ->  Conflict = nothing(X)
    ;   member(C1, Types),
        oro_disjoint_classes(Model, C1, C2),
        C1 @< C2,
        ord_memberchk(C2, Types),
        Conflict = disjoint(X, C1, C2)
    ).
individual_conflict(Model, checks(Fs, _, _, _, _), X, functional(P, X, V1, V2)) :-
    member(P, Fs),
    findall(V, oro_holds(Model, X, P, V), Vs),
    two_different(Model, Vs, V1, V2).
individual_conflict(Model, checks(_, IFs, _, _, _), X, inverse_functional(P, V, X1, X2)) :-
    member(P, IFs),
    (   V = X
    ;   oro_holds(Model, X, P, V)
    ),
    findall(Z, oro_holds(Model, Z, P, V), Zs),
    two_different(Model, Zs, X1, X2).
individual_conflict(Model, checks(_, _, Is, _, _), X, irreflexive(P, X)) :-
    member(P, Is),
    oro_holds(Model, X, P, X).
individual_conflict(Model, checks(_, _, _, As, _), X, Conflict) :-
    member(P, As),
    (   oro_holds(Model, X, P, Y),
        oro_holds(Model, Y, P, X)
    ->  msort([X, Y], [A, B]),
        Conflict = asymmetric(P, A, B)
    ).
individual_conflict(Model, checks(_, _, _, _, DPs), X, disjoint_properties(P, Q, X, Y)) :-
    member(P-Q, DPs),
    P @< Q,
    oro_holds(Model, X, P, Y),
    oro_holds(Model, X, Q, Y).

		 /*******************************
		 *        HYPOTHESES, ADDS      *
		 *******************************/

%!  oro_consistent_with(+Model, +Statements) is semidet.
%
%   Model is consistent and would stay so with Statements added: they
%   are added in a transaction that is always rolled back, so nothing
%   is kept and nobody sees them.  The check is incremental when Model
%   is known to be consistent.

oro_consistent_with(Model0, Statements) :-
    oro_resolve_model(Model0, Model),
    oro_complete_statements(Statements, Triples),
    catch(oro_store_write(check(Model), hypothesis(Model, Triples)),
          oro_hypothesis(Result),
          true),
    Result == true.

hypothesis(Model, Triples) :-
    (   consistent_before(check(Model), Model)
    ->  exclude(visible(Model), Triples, New),
        oro_store_assert(Model, Triples, longterm),
        (   new_conflict(Model, New)
        ->  throw(oro_hypothesis(false))
        ;   throw(oro_hypothesis(true))
        )
    ;   throw(oro_hypothesis(false))
    ).

%!  oro_safe_add(+Model, +Statements, +Profile, -Accepted) is det.
%
%   Add Statements to Model keeping it consistent (ORO's safeAdd): if
%   the model is consistent with all of them they are all added and
%   Accepted is `true`; otherwise each statement is tried in turn and
%   kept only if the model stays consistent, and Accepted is `false`.
%   If Model is inconsistent already, nothing is added.  One
%   transaction; the checks are incremental (see the module doc).

oro_safe_add(Model0, Statements, Profile0, Accepted) :-
    oro_resolve_model(Model0, Model),
    oro_memory_profile(Profile0, Profile),
    oro_complete_statements(Statements, Triples),
    oro_store_write(safe_add(Model),
                    safe_add(Model, Triples, Profile, Result, Gen0)),
    (   Result == false
    ->  Accepted = false
    ;   remember_after(Model, Gen0, true),
        (   Result == true
        ->  Accepted = true
        ;   Accepted = false
        )
    ).

%   Result is `true`, `partly` (the model stays consistent, some
%   statements were rejected) or `false` (inconsistent before).  Gen0
%   is the generation before the change, if known.

safe_add(Model, Triples, Profile, Accepted, Gen0) :-
    (   own_generation(safe_add(Model), Gen)
    ->  Gen0 = Gen
    ;   true
    ),
    (   \+ consistent_before(safe_add(Model), Model)
    ->  Accepted = false
    ;   exclude(visible(Model), Triples, New),
        oro_store_assert(Model, Triples, Profile),
        (   \+ new_conflict(Model, New)
        ->  oro_memory_remember(Model, Profile, Triples),
            Accepted = true
        ;   oro_store_retract(Model, New),
            foldl(try_triple(Model, Profile), New, [], Kept),
            oro_memory_remember(Model, Profile, Kept),
            Accepted = partly
        )
    ).

visible(Model, rdf(S, P, O)) :-
    oro_stored_term(S, P, O, Stored),
    oro_asserted(Model, S, P, Stored),
    !.

try_triple(Model, Profile, Triple, Kept0, Kept) :-
    (   visible(Model, Triple)
    ->  Kept = Kept0
    ;   oro_store_assert(Model, [Triple], Profile),
        (   new_conflict(Model, [Triple])
        ->  oro_store_retract(Model, [Triple]),
            Kept = Kept0
        ;   Kept = [Triple|Kept0]
        )
    ).
